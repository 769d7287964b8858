package raytracer.math;

/**
 * A mutable triple for the per-ray path: fields of a {@link raytracer.core.ShadeRec} and per-worker
 * scratch are overwritten in place instead of allocating a new vector for every hit.
 */
public final class MutableVec3 {
    public double x;
    public double y;
    public double z;

    public MutableVec3 set(double x, double y, double z) {
        this.x = x;
        this.y = y;
        this.z = z;
        return this;
    }

    public MutableVec3 set(MutableVec3 v) {
        return set(v.x, v.y, v.z);
    }

    public double dot(MutableVec3 v) {
        return x * v.x + y * v.y + z * v.z;
    }

    public double dot(double vx, double vy, double vz) {
        return x * vx + y * vy + z * vz;
    }

    public double length() {
        return Math.sqrt(x * x + y * y + z * z);
    }

    public MutableVec3 normalize() {
        double inv = 1.0 / length();
        x *= inv;
        y *= inv;
        z *= inv;
        return this;
    }

    public MutableVec3 negate() {
        x = -x;
        y = -y;
        z = -z;
        return this;
    }

    public Vector3D toVector() {
        return new Vector3D(x, y, z);
    }

    @Override
    public String toString() {
        return "(" + x + ", " + y + ", " + z + ")";
    }
}
