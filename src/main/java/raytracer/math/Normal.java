package raytracer.math;

/** An immutable surface normal; it transforms by the inverse transpose (see {@link Matrix4}). */
public record Normal(double x, double y, double z) {

    public Normal normalize() {
        double len = Math.sqrt(x * x + y * y + z * z);
        return new Normal(x / len, y / len, z / len);
    }

    public double dot(Vector3D v) {
        return x * v.x() + y * v.y() + z * v.z();
    }
}
