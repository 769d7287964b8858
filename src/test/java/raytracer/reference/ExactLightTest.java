package raytracer.reference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/**
 * The closed forms against an independent computation: the integral of cos(theta) cos(theta') / r^2
 * over the emitter by a 96 x 96 Gauss-Legendre product rule (for the disk in polar coordinates,
 * with a periodic trapezoid rule in the angle), and against the textbook corner formula.
 */
class ExactLightTest {
    private static final GaussLegendre RULE = new GaussLegendre(96);

    /** The projected solid angle of parallelogram corner + u a + v b (emitting along a x b) from p with normal n. */
    private static double numeric(Point3D corner, Vector3D a, Vector3D b, Point3D p, Vector3D n) {
        Vector3D axb = a.cross(b);
        double area = axb.length();
        Vector3D ne = axb.normalize();
        double sum = 0;
        for (int i = 0; i < RULE.order(); i++) {
            for (int j = 0; j < RULE.order(); j++) {
                Point3D q = corner.add(a.scale(RULE.node(i))).add(b.scale(RULE.node(j)));
                Vector3D d = q.sub(p);
                double r2 = d.dot(d);
                double cosLight = -ne.dot(d) / Math.sqrt(r2);
                double cosPoint = n.dot(d) / Math.sqrt(r2);
                if (cosLight > 0 && cosPoint > 0) {
                    sum += RULE.weight(i) * RULE.weight(j) * cosLight * cosPoint / r2;
                }
            }
        }
        return sum * area;
    }

    private static double lambert(Point3D corner, Vector3D a, Vector3D b, Point3D p, Vector3D n) {
        return PolygonLight.rectangle(corner, a, b).projectedSolidAngle(p.x(), p.y(), p.z(), n.x(), n.y(), n.z());
    }

    @Test
    void lambertsFormulaMatchesTheIntegralForParallelAndTiltedRectangles() {
        Vector3D up = new Vector3D(0, 1, 0);
        // a 2 x 1 rectangle at height 1.5 facing down, and one tilted 35 degrees about x
        Point3D corner = new Point3D(-1.5, 1.5, -0.5);
        Vector3D a = new Vector3D(2, 0, 0);
        Vector3D b = new Vector3D(0, 0, 1);
        Vector3D bTilted = new Vector3D(0, Math.sin(Math.toRadians(35)), Math.cos(Math.toRadians(35)));
        Point3D[] points = {new Point3D(0, 0, 0), new Point3D(-0.4, 0, 0.1), new Point3D(2.5, 0, -1.7),
                            new Point3D(-3, 0, 2), new Point3D(0.5, 0.7, 0.3)};
        for (Point3D p : points) {
            for (Vector3D edge : new Vector3D[] {b, bTilted}) {
                double expected = numeric(corner, a, edge, p, up);
                assertTrue(expected > 1e-3, "the test point should see the light: " + p);
                assertEquals(expected, lambert(corner, a, edge, p, up), 1e-9 * expected, "at " + p + ", edge-b " + edge);
            }
        }
        // a receiver that is itself tilted
        Vector3D n = new Vector3D(0.3, 1, -0.2).normalize();
        Point3D p = new Point3D(0.2, 0, 0.4);
        assertEquals(numeric(corner, a, b, p, n), lambert(corner, a, b, p, n), 1e-9);
    }

    @Test
    void lambertsFormulaMatchesTheCornerFormula() {
        // a rectangle X x Y parallel to the receiver, one corner straight above it at height h:
        // F = (X' atan(Y / sqrt(1 + X^2)) / sqrt(1 + X^2) ... ) / (2 pi) with X = x / h, Y = y / h, Omega = pi F
        double x = 1.7;
        double y = 0.6;
        double h = 1.1;
        double bx = x / h;
        double by = y / h;
        double f = (bx / Math.sqrt(1 + bx * bx) * Math.atan(by / Math.sqrt(1 + bx * bx))
                    + by / Math.sqrt(1 + by * by) * Math.atan(bx / Math.sqrt(1 + by * by))) / (2 * Math.PI);
        double omega = lambert(new Point3D(0, h, 0), new Vector3D(x, 0, 0), new Vector3D(0, 0, y), Point3D.ORIGIN, Vector3D.UP);
        assertEquals(Math.PI * f, omega, 1e-14);
    }

    @Test
    void aPointBehindTheEmittingSideGetsNothing() {
        Point3D corner = new Point3D(-1, 1, -1);
        Vector3D a = new Vector3D(2, 0, 0);
        Vector3D b = new Vector3D(0, 0, 2);
        assertTrue(lambert(corner, a, b, Point3D.ORIGIN, Vector3D.UP) > 0);
        // swapped edges emit upwards, away from the point
        assertEquals(0, lambert(corner, b, a, Point3D.ORIGIN, Vector3D.UP), 0);
        // above the light, looking down at its back
        assertEquals(0, lambert(corner, a, b, new Point3D(0, 2, 0), new Vector3D(0, -1, 0)), 0);
        PolygonLight light = PolygonLight.rectangle(corner, a, b);
        assertTrue(light.above(0, 0, 0, 0, 1, 0));
        assertFalse(light.above(0, 1, 0, 0, 1, 0), "a corner on the plane is not above it");
    }

    /** The disk's projected solid angle by quadrature in polar coordinates around its centre. */
    private static double numericDisk(double radius, double h, double rho) {
        int angles = 512;
        double sum = 0;
        for (int i = 0; i < RULE.order(); i++) {
            double r = radius * RULE.node(i);
            for (int k = 0; k < angles; k++) {
                double phi = 2 * Math.PI * k / angles;
                double dx = r * Math.cos(phi) - rho;
                double dz = r * Math.sin(phi);
                double d2 = dx * dx + dz * dz + h * h;
                // cos(theta) = cos(theta') = h / d for parallel planes
                sum += RULE.weight(i) * radius * r * (2 * Math.PI / angles) * h * h / (d2 * d2);
            }
        }
        return sum;
    }

    @Test
    void parallelDiskMatchesTheIntegralOnAndOffItsAxis() {
        double radius = 0.8;
        for (double h : new double[] {0.5, 1.3, 4}) {
            for (double rho : new double[] {0, 0.3, 0.8, 1.6, 5}) {
                double exact = new ParallelDiskLight(new Point3D(rho, h, 0), radius).projectedSolidAngle(0, 0, 0, 0, 1, 0);
                double expected = numericDisk(radius, h, rho);
                assertEquals(expected, exact, 1e-9 * expected, "h " + h + ", rho " + rho);
            }
            double onAxis = new ParallelDiskLight(new Point3D(0, h, 0), radius).projectedSolidAngle(0, 0, 0, 0, 1, 0);
            assertEquals(Math.PI * radius * radius / (h * h + radius * radius), onAxis, 1e-14);
        }
        assertEquals(0, new ParallelDiskLight(new Point3D(0, -1, 0), 1).projectedSolidAngle(0, 0, 0, 0, 1, 0), 0);
    }
}
