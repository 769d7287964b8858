package raytracer.lights;

import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Rounding;
import raytracer.math.SampleMapping;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/**
 * A disk emitting on the side its normal points to; sampled uniformly by area through the
 * concentric map, as pbrt-v4's Disk::Sample does from a reference point too.
 */
final class DiskEmitter implements Emitter {
    private final Point3D center;
    private final Vector3D normal;
    private final Vector3D e1;
    private final Vector3D e2;
    private final double radius;
    private final double inverseArea;

    DiskEmitter(Point3D center, Vector3D normal, double radius) {
        if (!(radius > 0) || !(normal.length() > 0)) {
            throw new IllegalArgumentException("a disk light needs a positive radius and a non-zero normal");
        }
        this.center = center;
        this.normal = normal.normalize();
        Vector3D helper = Math.abs(this.normal.x()) > 0.9 ? Vector3D.UP : new Vector3D(1, 0, 0);
        this.e1 = helper.cross(this.normal).normalize();
        this.e2 = this.normal.cross(e1);
        this.radius = radius;
        this.inverseArea = 1 / area();
    }

    /**
     * By the sample's error bound along the normal: the concentric map's sines and cosines, the
     * products and sums, and the stored basis, whose e1 and e2 are perpendicular to the normal only
     * to rounding, are well within gamma(16) of the centre's size plus the radius; plus two ulps of
     * that size, so that adding the move cannot round it away.
     */
    @Override
    public void moveOff(MutableVec3 point, MutableVec3 n) {
        double size = Math.max(Math.abs(center.x()), Math.max(Math.abs(center.y()), Math.abs(center.z()))) + radius;
        double move = Rounding.gamma(16) * size * (Math.abs(n.x) + Math.abs(n.y) + Math.abs(n.z)) + 0x1.0p-51 * size;
        point.set(point.x + move * n.x, point.y + move * n.y, point.z + move * n.z);
    }

    /** Uniform by area, whatever the point: density 1 / area. */
    @Override
    public double sample(MutableVec3 p, double u, double v, MutableVec3 point, MutableVec3 n) {
        // the point's disk coordinates go through n first, which is overwritten right after
        SampleMapping.toUnitDisk(u, v, n);
        double x = n.x * radius;
        double y = n.y * radius;
        point.set(center.x() + x * e1.x() + y * e2.x(), center.y() + x * e1.y() + y * e2.y(),
                  center.z() + x * e1.z() + y * e2.z());
        n.set(normal.x(), normal.y(), normal.z());
        return inverseArea;
    }

    @Override
    public double pdf(double px, double py, double pz, double distance, double cosLight) {
        return inverseArea;
    }

    @Override
    public boolean mayLight(MutableVec3 p, MutableVec3 n) {
        double cx = center.x() - p.x;
        double cy = center.y() - p.y;
        double cz = center.z() - p.z;
        if (normal.x() * cx + normal.y() * cy + normal.z() * cz >= 0) {
            return false;
        }
        // highest point of the disk over the tangent plane: the centre's height plus the radius
        // times the length of n's component in the disk's plane
        double nn = n.x * normal.x() + n.y * normal.y() + n.z * normal.z();
        return n.x * cx + n.y * cy + n.z * cz + radius * Math.sqrt(Math.max(0, 1 - nn * nn)) > 0;
    }

    /** The box of the sphere around the disk: looser than the disk's own, never smaller. */
    @Override
    public BBox bounds() {
        return new BBox(center.x() - radius, center.y() - radius, center.z() - radius,
                        center.x() + radius, center.y() + radius, center.z() + radius);
    }

    @Override
    public double area() {
        return Math.PI * radius * radius;
    }
}
