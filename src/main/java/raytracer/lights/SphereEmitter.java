package raytracer.lights;

import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Rounding;
import raytracer.math.MutableVec3;

/**
 * A sphere emitting outward, sampled uniformly over its whole area (z = 1 - 2u, phi = 2 pi v):
 * points on the far side get cos(theta_light) below 0 and weigh nothing, so the estimate stays
 * unbiased, if noisier than sampling the visible cap.
 */
final class SphereEmitter implements Emitter {
    private final Point3D center;
    private final double radius;

    SphereEmitter(Point3D center, double radius) {
        if (!(radius > 0)) {
            throw new IllegalArgumentException("a sphere light needs a positive radius, got " + radius);
        }
        this.center = center;
        this.radius = radius;
    }

    /**
     * By the sample's error bound along the normal: the unit vector from a square root, a sine and
     * a cosine, times the radius, plus the centre, is within gamma(16) of their sizes; plus two
     * ulps of that size, so that adding the move cannot round it away.
     */
    @Override
    public void moveOff(MutableVec3 point, MutableVec3 n) {
        double size = Math.max(Math.abs(center.x()), Math.max(Math.abs(center.y()), Math.abs(center.z()))) + radius;
        double move = Rounding.gamma(16) * size * (Math.abs(n.x) + Math.abs(n.y) + Math.abs(n.z)) + 0x1.0p-51 * size;
        point.set(point.x + move * n.x, point.y + move * n.y, point.z + move * n.z);
    }

    @Override
    public void sample(double u, double v, MutableVec3 point, MutableVec3 n) {
        double z = 1 - 2 * u;
        double r = Math.sqrt(Math.max(0, 1 - z * z));
        double phi = 2 * Math.PI * v;
        n.set(r * Math.cos(phi), r * Math.sin(phi), z);
        point.set(center.x() + radius * n.x, center.y() + radius * n.y, center.z() + radius * n.z);
    }

    @Override
    public boolean mayLight(MutableVec3 p, MutableVec3 n) {
        return n.x * (center.x() - p.x) + n.y * (center.y() - p.y) + n.z * (center.z() - p.z) + radius > 0;
    }

    @Override
    public BBox bounds() {
        return new BBox(center.x() - radius, center.y() - radius, center.z() - radius,
                        center.x() + radius, center.y() + radius, center.z() + radius);
    }

    @Override
    public double area() {
        return 4 * Math.PI * radius * radius;
    }
}
