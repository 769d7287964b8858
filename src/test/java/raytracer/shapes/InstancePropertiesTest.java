package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static raytracer.PropertyCheck.forAll;
import static raytracer.PropertyCheck.logUniform;
import static raytracer.PropertyCheck.unitVector;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/**
 * An instance is the object moved: hits found through the inverse transform and brought back agree
 * with the same shape built in place, at scales 1e-4 to 1e6 and up to 1e4 sizes from the origin.
 */
class InstancePropertiesTest {
    private static final int TRIES = 500;
    private static final int RAYS = 10;
    /** Distances and points agree to 1e-9 of the sizes involved: the arithmetic loses a few ulps of them. */
    private static final double TOLERANCE = 1e-9;

    /** A unit sphere scaled by s, turned and moved is the sphere of radius s at the moved centre. */
    @Test
    void aMovedSphereIsTheSphereBuiltThere() {
        forAll("instance of a sphere = sphere in place", TRIES, random -> {
            double s = logUniform(random, 1e-4, 1e6);
            double shift = random.nextBoolean() ? 0 : s * logUniform(random, 1, 1e4);
            double[] d = unitVector(random);
            Matrix4 m = Matrix4.translate(shift * d[0], shift * d[1], shift * d[2]).multiply(Matrix4.scale(s, s, s))
                .multiply(Matrix4.rotateY(random.nextDouble(360))).multiply(Matrix4.rotateX(random.nextDouble(360)));
            Instance moved = new Instance(new Sphere(Point3D.ORIGIN, 1), m);
            Point3D centre = m.transform(Point3D.ORIGIN);
            Sphere built = new Sphere(centre, s);
            HitTesting h = new HitTesting();
            for (int i = 0; i < RAYS; i++) {
                Ray ray = rayAtBall(random, centre, s);
                ShadeRec a = h.hit(moved, ray);
                assertNotNull(a, "the instance is missed");
                double t = a.t;
                double[] point = {a.hitPoint.x, a.hitPoint.y, a.hitPoint.z};
                double[] normal = {a.normal.x, a.normal.y, a.normal.z};
                ShadeRec b = h.hit(built, ray);
                assertNotNull(b, "the sphere is missed");
                double length = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
                String what = "scale " + s + ", shift " + shift + ", ray " + i;
                assertEquals(b.t, t, TOLERANCE * (s + shift) / length, what + ": distance");
                assertEquals(b.hitPoint.x, point[0], TOLERANCE * (s + shift), what + ": hit point x");
                assertEquals(b.hitPoint.y, point[1], TOLERANCE * (s + shift), what + ": hit point y");
                assertEquals(b.hitPoint.z, point[2], TOLERANCE * (s + shift), what + ": hit point z");
                // the normal's direction is fixed by s / (point - centre), good to shift / s ulps
                double normalTolerance = TOLERANCE * (1 + shift / s);
                assertEquals(b.normal.x, normal[0], normalTolerance, what + ": normal x");
                assertEquals(b.normal.y, normal[1], normalTolerance, what + ": normal y");
                assertEquals(b.normal.z, normal[2], normalTolerance, what + ": normal z");
            }
        });
    }

    /**
     * Under any affine transform (scales up to 100:1 between axes, a mirror half the time), the hit
     * point taken back into the box's space lies on its surface, and the normal is perpendicular to
     * the moved edges of the face hit.
     */
    @Test
    void aMovedBoxIsHitOnItsSurfaceWithTheMovedNormal() {
        forAll("instance of a box: hit on the surface, normal perpendicular to the face", TRIES, random -> {
            double s = logUniform(random, 1e-4, 1e6);
            double shift = random.nextBoolean() ? 0 : s * logUniform(random, 1, 1e4);
            double[] d = unitVector(random);
            double[] h = {logUniform(random, 0.1, 10), logUniform(random, 0.1, 10), logUniform(random, 0.1, 10)};
            Matrix4 m = Matrix4.translate(shift * d[0], shift * d[1], shift * d[2])
                .multiply(Matrix4.rotateZ(random.nextDouble(360))).multiply(Matrix4.rotateX(random.nextDouble(360)))
                .multiply(Matrix4.scale(random.nextBoolean() ? -s : s, s * logUniform(random, 0.1, 10), s))
                .multiply(Matrix4.rotateY(random.nextDouble(360)));
            Instance moved = new Instance(new Box(new Point3D(-h[0], -h[1], -h[2]), new Point3D(h[0], h[1], h[2])), m);
            Matrix4 inverse = m.inverse();
            HitTesting hits = new HitTesting();
            double[] axis = new double[3];
            for (int i = 0; i < RAYS; i++) {
                double[] inside = {random.nextDouble(-0.9, 0.9) * h[0], random.nextDouble(-0.9, 0.9) * h[1], random.nextDouble(-0.9, 0.9) * h[2]};
                Point3D target = m.transform(new Point3D(inside[0], inside[1], inside[2]));
                double[] w = unitVector(random);
                double far = 50 * s * (h[0] + h[1] + h[2]);
                Ray ray = new Ray().set(target.x() + far * w[0], target.y() + far * w[1], target.z() + far * w[2], -w[0], -w[1], -w[2]);
                ShadeRec sr = hits.hit(moved, ray);
                String what = "scale " + s + ", shift " + shift + ", ray " + i;
                assertNotNull(sr, what + ": the box is missed");
                Point3D local = inverse.transform(new Point3D(sr.hitPoint.x, sr.hitPoint.y, sr.hitPoint.z));
                double[] q = {local.x() / h[0], local.y() / h[1], local.z() / h[2]};
                int face = Math.abs(q[0]) > Math.abs(q[1]) ? (Math.abs(q[0]) > Math.abs(q[2]) ? 0 : 2) : (Math.abs(q[1]) > Math.abs(q[2]) ? 1 : 2);
                // in the box's space the arithmetic is good to shift / s of its unit sizes
                double slack = TOLERANCE * (1 + shift / s) * 100;
                assertEquals(1, Math.abs(q[face]), slack, what + ": the hit point is on the surface");
                for (int k = 1; k <= 2; k++) {
                    java.util.Arrays.fill(axis, 0);
                    axis[(face + k) % 3] = 1;
                    Vector3D edge = m.transform(new Vector3D(axis[0], axis[1], axis[2])).normalize();
                    double cos = edge.x() * sr.normal.x + edge.y() * sr.normal.y + edge.z() * sr.normal.z;
                    assertEquals(0, cos, TOLERANCE, what + ": the normal is perpendicular to the face");
                }
            }
        });
    }

    /** A ray from well outside towards a random point of the ball of radius 0.9 r: a sure hit, never grazing. */
    private static Ray rayAtBall(SplittableRandom random, Point3D centre, double r) {
        double[] u = unitVector(random);
        double depth = 0.9 * r * Math.cbrt(random.nextDouble());
        double[] w = unitVector(random);
        double far = r * logUniform(random, 2, 1000);
        double tx = centre.x() + depth * u[0];
        double ty = centre.y() + depth * u[1];
        double tz = centre.z() + depth * u[2];
        return new Ray().set(tx + far * w[0], ty + far * w[1], tz + far * w[2], -far * w[0], -far * w[1], -far * w[2]);
    }
}
