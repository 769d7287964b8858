package raytracer.reference;

import raytracer.math.Point3D;

/**
 * A disk of radius R emitting towards a receiving plane parallel to it. From a point at height h
 * under the disk's plane and at distance rho from its axis, the configuration factor is
 * F = (1/2) (1 - (h^2 + rho^2 - R^2) / sqrt((h^2 + rho^2 + R^2)^2 - 4 R^2 rho^2))
 * (the differential area to parallel disk case of Howell's catalog of configuration factors), and the
 * projected solid angle is pi F. On the axis this is pi R^2 / (h^2 + R^2).
 */
public final class ParallelDiskLight implements ExactLight {
    private final Point3D center;
    private final double radius;

    /** A disk centred at {@code center} in a plane parallel to the receiver, facing it. */
    public ParallelDiskLight(Point3D center, double radius) {
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("a disk needs a positive radius, got " + radius);
        }
        this.center = center;
        this.radius = radius;
    }

    /** The formula holds for receivers with normal n parallel to the disk's axis, the disk on n's side. */
    @Override
    public double projectedSolidAngle(double px, double py, double pz, double nx, double ny, double nz) {
        double dx = center.x() - px;
        double dy = center.y() - py;
        double dz = center.z() - pz;
        double h = dx * nx + dy * ny + dz * nz;
        if (!(h > 0)) {
            return 0;
        }
        double rho2 = Math.max(0, dx * dx + dy * dy + dz * dz - h * h);
        double r2 = radius * radius;
        double h2 = h * h;
        double root = Math.sqrt((h2 + rho2 + r2) * (h2 + rho2 + r2) - 4 * r2 * rho2);
        return Math.PI / 2 * (1 - (h2 + rho2 - r2) / root);
    }

    @Override
    public boolean above(double px, double py, double pz, double nx, double ny, double nz) {
        return (center.x() - px) * nx + (center.y() - py) * ny + (center.z() - pz) * nz > 0;
    }
}
