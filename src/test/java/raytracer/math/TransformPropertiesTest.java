package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.PropertyCheck.forAll;
import static raytracer.PropertyCheck.logUniform;
import static raytracer.PropertyCheck.unitVector;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * Round trips through random affine transforms: an overall scale of 1e-4 to 1e6 with up to 100:1
 * between axes (a mirror half the time), two turns, a shift up to 1e4 sizes. Rounding allows an
 * error of about (condition number) x (a few ulps) of the magnitudes involved; the bound used is
 * 1e-11 of them, for a condition number up to 1e4 (the anisotropy squared, at worst).
 */
class TransformPropertiesTest {
    private static final int TRIES = 1000;
    private static final double TOLERANCE = 1e-11;

    @Test
    void inverseUndoesTheTransform() {
        forAll("M^-1 M = I on points and vectors", TRIES, random -> {
            Affine a = Affine.random(random);
            Matrix4 inverse = a.m.inverse();
            double[] p = point(random, a.scale);
            Point3D back = inverse.transform(a.m.transform(new Point3D(p[0], p[1], p[2])));
            double size = norm(p) + a.shift / a.scale;
            assertEquals(p[0], back.x(), TOLERANCE * size, a + ": point x");
            assertEquals(p[1], back.y(), TOLERANCE * size, a + ": point y");
            assertEquals(p[2], back.z(), TOLERANCE * size, a + ": point z");
            double[] v = unitVector(random);
            Vector3D w = inverse.transform(a.m.transform(new Vector3D(v[0], v[1], v[2])));
            assertEquals(v[0], w.x(), TOLERANCE, a + ": vector x");
            assertEquals(v[1], w.y(), TOLERANCE, a + ": vector y");
            assertEquals(v[2], w.z(), TOLERANCE, a + ": vector z");
            Matrix4 identity = a.m.multiply(inverse);
            for (int row = 0; row < 3; row++) {
                for (int col = 0; col < 3; col++) {
                    assertEquals(row == col ? 1 : 0, identity.get(row, col), TOLERANCE, a + ": (M M^-1)[" + row + "][" + col + "]");
                }
                assertEquals(0, identity.get(row, 3), TOLERANCE * a.shift, a + ": translation of M M^-1");
            }
        });
    }

    @Test
    void inverseOfAProductIsTheProductOfInversesReversed() {
        forAll("(A B)^-1 = B^-1 A^-1", TRIES, random -> {
            Affine a = Affine.random(random);
            Affine b = Affine.random(random);
            Matrix4 left = a.m.multiply(b.m).inverse();
            Matrix4 right = b.m.inverse().multiply(a.m.inverse());
            double[] p = point(random, a.scale * b.scale);
            Point3D x = left.transform(new Point3D(p[0], p[1], p[2]));
            Point3D y = right.transform(new Point3D(p[0], p[1], p[2]));
            double size = norm(new double[] {x.x(), x.y(), x.z()}) + norm(p) / (a.scale * b.scale) + a.shift / a.scale + b.shift / b.scale;
            assertEquals(x.x(), y.x(), 10 * TOLERANCE * size, a + " then " + b);
            assertEquals(x.y(), y.y(), 10 * TOLERANCE * size, a + " then " + b);
            assertEquals(x.z(), y.z(), 10 * TOLERANCE * size, a + " then " + b);
        });
    }

    /** A normal taken through (M^-1)^T stays perpendicular to every tangent taken through M. */
    @Test
    void normalsStayPerpendicularToTransformedTangents() {
        forAll("(M^-1)^T n is perpendicular to M t", TRIES, random -> {
            Affine a = Affine.random(random);
            double[] n = unitVector(random);
            double[] u = unitVector(random);
            // a tangent: u without its component along n
            double un = u[0] * n[0] + u[1] * n[1] + u[2] * n[2];
            MutableVec3 tangent = new MutableVec3().set(u[0] - un * n[0], u[1] - un * n[1], u[2] - un * n[2]);
            if (tangent.length() < 1e-3) {
                return;
            }
            a.m.transformVector(tangent);
            MutableVec3 normal = new MutableVec3().set(n[0], n[1], n[2]);
            a.m.inverse().transformNormalByInverse(normal);
            double cos = tangent.dot(normal) / (tangent.length() * normal.length());
            assertEquals(0, cos, TOLERANCE, a.toString());
        });
    }

    /** The ray's parameter t names the same point in both spaces, since the direction is not renormalised. */
    @Test
    void aRayKeepsItsParameterInTheObjectsSpace() {
        forAll("M^-1 (o + t d) = o' + t d'", TRIES, random -> {
            Affine a = Affine.random(random);
            Matrix4 inverse = a.m.inverse();
            double[] o = point(random, a.scale);
            double[] d = unitVector(random);
            double t = a.scale * logUniform(random, 1e-3, 1e3);
            Ray local = new Ray();
            inverse.transformRay(new Ray().set(o[0], o[1], o[2], d[0], d[1], d[2]), local);
            Point3D expected = inverse.transform(new Point3D(o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]));
            double size = (norm(o) + t + a.shift) / a.scale;
            assertEquals(expected.x(), local.ox + t * local.dx, 10 * TOLERANCE * size, a.toString());
            assertEquals(expected.y(), local.oy + t * local.dy, 10 * TOLERANCE * size, a.toString());
            assertEquals(expected.z(), local.oz + t * local.dz, 10 * TOLERANCE * size, a.toString());
        });
    }

    /** The transformed box of a box holds the transform of every point of the box. */
    @Test
    void aTransformedBoxHoldsTheTransformedPoints() {
        forAll("M(box) contains M(p) for p in box", TRIES, random -> {
            Affine a = Affine.random(random);
            double[] c = point(random, 1);
            double[] h = {logUniform(random, 1e-3, 1), logUniform(random, 1e-3, 1), logUniform(random, 1e-3, 1)};
            BBox box = a.m.transform(new BBox(c[0] - h[0], c[1] - h[1], c[2] - h[2], c[0] + h[0], c[1] + h[1], c[2] + h[2]));
            for (int i = 0; i < 20; i++) {
                // corners included: they are where rounding could push a point out
                double[] s = new double[3];
                for (int k = 0; k < 3; k++) {
                    s[k] = random.nextInt(4) == 0 ? (random.nextBoolean() ? -1 : 1) : random.nextDouble(-1, 1);
                }
                Point3D q = a.m.transform(new Point3D(c[0] + s[0] * h[0], c[1] + s[1] * h[1], c[2] + s[2] * h[2]));
                assertTrue(box.contains(q.x(), q.y(), q.z()), a + ": " + q + " outside " + box);
            }
        });
    }

    private static double[] point(SplittableRandom random, double scale) {
        double[] d = unitVector(random);
        double r = scale * logUniform(random, 1e-3, 1e3);
        return new double[] {r * d[0], r * d[1], r * d[2]};
    }

    private static double norm(double[] v) {
        return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }

    /** A random affine transform and what it was made of, for the message. */
    private record Affine(Matrix4 m, double scale, double shift, String text) {
        static Affine random(SplittableRandom random) {
            double scale = logUniform(random, 1e-4, 1e6);
            double sx = scale * logUniform(random, 0.1, 10) * (random.nextBoolean() ? -1 : 1);
            double sy = scale * logUniform(random, 0.1, 10);
            double sz = scale * logUniform(random, 0.1, 10);
            double shift = random.nextBoolean() ? 0 : scale * logUniform(random, 1, 1e4);
            double[] d = unitVector(random);
            double y1 = random.nextDouble(360);
            double x1 = random.nextDouble(360);
            double z2 = random.nextDouble(360);
            Matrix4 m = Matrix4.translate(shift * d[0], shift * d[1], shift * d[2])
                .multiply(Matrix4.rotateY(y1)).multiply(Matrix4.rotateX(x1))
                .multiply(Matrix4.scale(sx, sy, sz))
                .multiply(Matrix4.rotateZ(z2));
            String text = String.format("translate %.3g, rotate-y %.1f, rotate-x %.1f, scale (%.3g, %.3g, %.3g), rotate-z %.1f",
                                        shift, y1, x1, sx, sy, sz, z2);
            return new Affine(m, Math.abs(scale), shift, text);
        }

        @Override
        public String toString() {
            return text;
        }
    }
}
