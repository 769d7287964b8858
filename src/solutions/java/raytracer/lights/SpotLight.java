package raytracer.lights;

import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/**
 * Reference solution of exercise 3 (docs/teaching.md): a point light of intensity I = ls c that
 * shines into a cone: I / r^2 within {@code falloffStart} degrees of its axis, nothing beyond
 * {@code totalAngle}, and between them I / r^2 times ((cos(theta) - cos(total)) / (cos(start) -
 * cos(total)))^4, the smooth edge of pbrt-v3's spot light (section 12.2.1).
 */
public final class SpotLight extends Light {
    private final double px;
    private final double py;
    private final double pz;
    /** The unit axis of the cone. */
    private final double ax;
    private final double ay;
    private final double az;
    private final double cosTotal;
    private final double cosStart;
    private final RGBColor intensity;

    public SpotLight(double ls, RGBColor color, Point3D position, Vector3D direction, double totalAngle, double falloffStart) {
        if (!(totalAngle > 0 && totalAngle < 180 && falloffStart >= 0 && falloffStart <= totalAngle)) {
            throw new IllegalArgumentException("a spot light needs 0 <= falloff start <= total angle < 180 degrees, total > 0; got total "
                                               + totalAngle + ", start " + falloffStart);
        }
        double length = direction.length();
        if (!(length > 0) || !Double.isFinite(length)) {
            throw new IllegalArgumentException("a spot light's direction must be finite and non-zero, got " + direction);
        }
        this.px = position.x();
        this.py = position.y();
        this.pz = position.z();
        this.ax = direction.x() / length;
        this.ay = direction.y() / length;
        this.az = direction.z() / length;
        this.cosTotal = Math.cos(Math.toRadians(totalAngle));
        this.cosStart = Math.cos(Math.toRadians(falloffStart));
        this.intensity = color.scale(ls);
    }

    @Override
    public double getDirection(ShadeRec sr, MutableVec3 wi) {
        wi.set(px - sr.hitPoint.x, py - sr.hitPoint.y, pz - sr.hitPoint.z);
        double distance = wi.length();
        wi.set(wi.x / distance, wi.y / distance, wi.z / distance);
        return distance;
    }

    @Override
    public void L(ShadeRec sr, MutableRgb out) {
        double dx = sr.hitPoint.x - px;
        double dy = sr.hitPoint.y - py;
        double dz = sr.hitPoint.z - pz;
        double r2 = dx * dx + dy * dy + dz * dz;
        // cos(theta) between the axis and the way from the light to the point
        double cos = (dx * ax + dy * ay + dz * az) / Math.sqrt(r2);
        out.set(intensity).scale(falloff(cos) / r2);
    }

    @Override
    public boolean mayIlluminate(ShadeRec sr) {
        double dx = sr.hitPoint.x - px;
        double dy = sr.hitPoint.y - py;
        double dz = sr.hitPoint.z - pz;
        return dx * ax + dy * ay + dz * az > cosTotal * Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    private double falloff(double cos) {
        if (cos >= cosStart) {
            return 1;
        }
        if (cos <= cosTotal) {
            return 0;
        }
        double delta = (cos - cosTotal) / (cosStart - cosTotal);
        return (delta * delta) * (delta * delta);
    }
}
