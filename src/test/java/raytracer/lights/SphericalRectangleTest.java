package raytracer.lights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.math.MutableVec3;

/**
 * The spherical rectangle's solid angle and map against an independent closed form: the solid
 * angle of [x0, x1] x [y0, y1] at height h under it is F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0)
 * with F(x, y) = atan(x y / (h sqrt(x^2 + y^2 + h^2))), accurate to a few 1e-16 absolutely. The map
 * preserves solid angle: the column it picks for u leaves a share u of the solid angle on its x0
 * side, and the point it picks for v a share v of the column's (uniform in y / sqrt(d^2 + y^2),
 * d^2 = x_u^2 + z0^2, the sine of the elevation along the column). Seeded random rectangles and
 * points across scales 1e-4 to 1e6, at every distance and angle, grazing ones included.
 */
class SphericalRectangleTest {

    private static double f(double x, double y, double h) {
        return Math.atan(x * y / (h * Math.sqrt(x * x + y * y + h * h)));
    }

    private static double cornerFormula(double x0, double y0, double x1, double y1, double z0) {
        double h = -z0;
        return f(x1, y1, h) - f(x0, y1, h) - f(x1, y0, h) + f(x0, y0, h);
    }

    /** y_a / l_a - y_b / l_b, l = sqrt(d2 + y^2), without cancellation. */
    private static double sineDifference(double ya, double yb, double d2) {
        double la = Math.sqrt(d2 + ya * ya);
        double lb = Math.sqrt(d2 + yb * yb);
        if (ya * yb > 0) {
            return d2 * (ya * ya - yb * yb) / (ya * lb + yb * la) / (la * lb);
        }
        return ya / la - yb / lb;
    }

    @Test
    void theSolidAngleAndTheMapAreRightAcrossScales() {
        SplittableRandom random = new SplittableRandom(11);
        MutableVec3 out = new MutableVec3();
        int mapped = 0;
        double worstS = 0;
        double worstU = 0;
        double worstV = 0;
        for (int i = 0; i < 40_000; i++) {
            double scale = Math.exp(random.nextDouble(Math.log(1e-4), Math.log(1e6)));
            double w = scale * Math.exp(random.nextDouble(-3, 3));
            double h = scale * Math.exp(random.nextDouble(-3, 3));
            double far = scale * Math.exp(random.nextDouble(-8, 8));
            double x0 = random.nextDouble(-1, 1) * far - w / 2;
            double y0 = random.nextDouble(-1, 1) * far * (random.nextBoolean() ? 1 : 1e-3) - h / 2;
            double z0 = -far * Math.exp(random.nextDouble(-25, 2));
            // the emitter's normalisation, so that nothing overflows
            double norm = 1 / (Math.abs(x0) + Math.abs(y0) - z0 + w + h);
            x0 *= norm;
            y0 *= norm;
            z0 *= norm;
            double x1 = x0 + w * norm;
            double y1 = y0 + h * norm;
            double solidAngle = SphericalRectangle.solidAngle(x0, y0, x1, y1, z0);
            if (solidAngle < SphericalRectangle.MIN_SOLID_ANGLE) {
                continue;
            }
            double exact = cornerFormula(x0, y0, x1, y1, z0);
            worstS = Math.max(worstS, Math.abs(solidAngle - exact) / exact);
            double k = SphericalRectangle.edgeAngle(x0, y0, y1, z0);
            for (int j = 0; j < 10; j++) {
                double u = random.nextDouble();
                double v = random.nextDouble();
                SphericalRectangle.sample(x0, y0, x1, y1, z0, solidAngle, k, u, v, out);
                assertTrue(out.x >= x0 && out.x <= x1 && out.y >= y0 && out.y <= y1, "on the rectangle");
                double d2 = out.x * out.x + z0 * z0;
                worstU = Math.max(worstU, Math.abs(cornerFormula(x0, y0, out.x, y1, z0) / exact - u));
                worstV = Math.max(worstV, Math.abs(sineDifference(out.y, y0, d2) / sineDifference(y1, y0, d2) - v));
                mapped++;
            }
        }
        assertTrue(mapped > 100_000, "enough rectangles above the threshold: " + mapped);
        assertTrue(worstS < 1e-8, "solid angle, relative: " + worstS);
        assertTrue(worstU < 1e-6, "share of the solid angle left of the column: " + worstU);
        assertTrue(worstV < 1e-9, "share of the column below the point: " + worstV);
    }

    /** The corners of [0,1)^2 go to the corners of the rectangle, and the middle to the middle of its solid angle. */
    @Test
    void theMapIsContinuousUpToTheEdges() {
        double x0 = -0.3;
        double x1 = 0.9;
        double y0 = 0.2;
        double y1 = 0.7;
        double z0 = -0.4;
        double s = SphericalRectangle.solidAngle(x0, y0, x1, y1, z0);
        double k = SphericalRectangle.edgeAngle(x0, y0, y1, z0);
        MutableVec3 out = new MutableVec3();
        SphericalRectangle.sample(x0, y0, x1, y1, z0, s, k, 0, 0, out);
        assertEquals(x0, out.x, 1e-12);
        assertEquals(y0, out.y, 1e-12);
        SphericalRectangle.sample(x0, y0, x1, y1, z0, s, k, Math.nextDown(1.0), Math.nextDown(1.0), out);
        assertEquals(x1, out.x, 1e-12);
        assertEquals(y1, out.y, 1e-12);
        SphericalRectangle.sample(x0, y0, x1, y1, z0, s, k, 0.5, 0.5, out);
        assertEquals(0.5 * s, cornerFormula(x0, y0, out.x, y1, z0), 1e-14);
    }

    /** In the rectangle's plane (or behind it, which the emitter turns round) the solid angle is 0. */
    @Test
    void aPointInThePlaneSeesNoSolidAngle() {
        assertEquals(0, SphericalRectangle.solidAngle(-1, -1, 1, 1, 0));
        assertEquals(0, SphericalRectangle.solidAngle(-1, -1, 1, 1, -0.0));
        assertEquals(0, SphericalRectangle.solidAngle(2, 3, 4, 5, 0));
        assertEquals(0, SphericalRectangle.solidAngle(-1, -1, 1, 1, 1));
    }
}
