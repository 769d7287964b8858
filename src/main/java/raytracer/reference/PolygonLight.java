package raytracer.reference;

import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/**
 * A planar convex polygon emitting on the side of its normal (e1 x e2 for the vertices in order).
 * Its projected solid angle is Lambert's formula (1760; as written in Arvo, "The irradiance Jacobian
 * for partially occluded polyhedral sources", SIGGRAPH 1994): (1/2) |sum_i Theta_i (n . Gamma_i)|, with
 * Theta_i the angle the i-th edge subtends at the point and Gamma_i the unit normal of the plane
 * through the point and that edge. Exact when the whole polygon lies above the point's horizon.
 */
public final class PolygonLight implements ExactLight {
    private final double[] vertices;
    private final double ex;
    private final double ey;
    private final double ez;

    public PolygonLight(Point3D... corners) {
        if (corners.length < 3) {
            throw new IllegalArgumentException("a polygon needs at least 3 corners, got " + corners.length);
        }
        vertices = new double[3 * corners.length];
        for (int i = 0; i < corners.length; i++) {
            vertices[3 * i] = corners[i].x();
            vertices[3 * i + 1] = corners[i].y();
            vertices[3 * i + 2] = corners[i].z();
        }
        Vector3D normal = corners[1].sub(corners[0]).cross(corners[2].sub(corners[1]));
        if (!(normal.length() > 0)) {
            throw new IllegalArgumentException("the polygon's first three corners lie on one line");
        }
        Vector3D unit = normal.normalize();
        ex = unit.x();
        ey = unit.y();
        ez = unit.z();
    }

    /** The parallelogram corner + u a + v b (u, v in [0, 1]), emitting on the side of a x b, as the scene's rectangle light. */
    public static PolygonLight rectangle(Point3D corner, Vector3D a, Vector3D b) {
        return new PolygonLight(corner, corner.add(a), corner.add(a).add(b), corner.add(b));
    }

    @Override
    public double projectedSolidAngle(double px, double py, double pz, double nx, double ny, double nz) {
        int m = vertices.length / 3;
        // the emitting side faces p only when p lies on the side the emission normal points to
        if ((px - vertices[0]) * ex + (py - vertices[1]) * ey + (pz - vertices[2]) * ez <= 0) {
            return 0;
        }
        double sum = 0;
        for (int i = 0; i < m; i++) {
            int j = (i + 1) % m;
            double ax = vertices[3 * i] - px;
            double ay = vertices[3 * i + 1] - py;
            double az = vertices[3 * i + 2] - pz;
            double bx = vertices[3 * j] - px;
            double by = vertices[3 * j + 1] - py;
            double bz = vertices[3 * j + 2] - pz;
            double cx = ay * bz - az * by;
            double cy = az * bx - ax * bz;
            double cz = ax * by - ay * bx;
            double crossLength = Math.sqrt(cx * cx + cy * cy + cz * cz);
            if (crossLength == 0) {
                continue; // p on the edge's line: the edge subtends no angle
            }
            // the angle between a and b from atan2, accurate for small and for obtuse angles alike
            double theta = Math.atan2(crossLength, ax * bx + ay * by + az * bz);
            sum += theta * (cx * nx + cy * ny + cz * nz) / crossLength;
        }
        return Math.abs(sum) / 2;
    }

    @Override
    public boolean above(double px, double py, double pz, double nx, double ny, double nz) {
        for (int i = 0; i < vertices.length; i += 3) {
            if (!((vertices[i] - px) * nx + (vertices[i + 1] - py) * ny + (vertices[i + 2] - pz) * nz > 0)) {
                return false;
            }
        }
        return true;
    }
}
