package raytracer.lights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/**
 * A light's {@code directionPdf} is the density, per unit solid angle seen from a point, with which
 * its own sampling chooses a direction: over the directions that reach the light it integrates to
 * the share of samples that can reach the point, 1 for every light here (a rectangle or a sphere
 * sampled by the solid angle it covers, a disk or a parallelogram by area). Checked by integrating
 * it over directions, with the hit on the light found here by plain geometry ({@link LightHits}),
 * from points that see the light at grazing angles (a cosine at the light well below 1, where
 * dropping that cosine from d^2 / (A cos) would show: it feeds the MIS weight of glossy rays that
 * hit a visible light), close up, and so far that a rectangle is sampled by area.
 */
class DirectionPdfTest {
    /** Grid cells per side of the gnomonic plane one unit from the point, across the light's directions. */
    private static final int CELLS = 1500;

    /**
     * The integral of the light's density over the directions from {@code p} that meet it, by the
     * midpoint rule on the plane through {@code p + w} perpendicular to {@code w} (the direction
     * to the light's centre): dω = cos^3(α) dx dy there, α the angle from {@code w}.
     */
    static double integrate(AreaLight light, Point3D p, Vector3D towards, double halfWidth, LightHits g) {
        Vector3D w = towards.normalize();
        Vector3D helper = Math.abs(w.x()) < 0.9 ? new Vector3D(1, 0, 0) : new Vector3D(0, 1, 0);
        Vector3D e1 = helper.cross(w).normalize();
        Vector3D e2 = w.cross(e1);
        double h = 2 * halfWidth / CELLS;
        double sum = 0;
        int hits = 0;
        for (int i = 0; i < CELLS; i++) {
            double x = -halfWidth + (i + 0.5) * h;
            for (int j = 0; j < CELLS; j++) {
                double y = -halfWidth + (j + 0.5) * h;
                double dx = w.x() + x * e1.x() + y * e2.x();
                double dy = w.y() + x * e1.y() + y * e2.y();
                double dz = w.z() + x * e1.z() + y * e2.z();
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double[] hit = g.hit(dx / len, dy / len, dz / len);
                boolean border = i == 0 || j == 0 || i == CELLS - 1 || j == CELLS - 1;
                assertTrue(hit == null || !border, "the grid must hold the whole light");
                if (hit != null) {
                    double cosAlpha = 1 / len;
                    double pdf = light.directionPdf(p.x(), p.y(), p.z(), hit[0], hit[1]);
                    assertTrue(pdf > 0 && pdf < Double.POSITIVE_INFINITY, "a finite density: " + pdf);
                    sum += pdf * cosAlpha * cosAlpha * cosAlpha * h * h;
                    hits++;
                }
            }
        }
        assertTrue(hits > 100_000, "the light is resolved: " + hits + " cells hit");
        return sum;
    }

    @Test
    void aRectangleSeenAtAGrazingAngleIntegratesToOne() {
        // the light spans x, z in [-1, 1] at y = 2, facing down; the point sees its centre 18 degrees above its plane
        Point3D corner = new Point3D(-1, 2, -1);
        Vector3D a = new Vector3D(0, 0, 2);
        Vector3D b = new Vector3D(2, 0, 0);
        AreaLight light = AreaLight.rectangle(corner, a, b, 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(6, 0, 0);
        double cosAtCentre = 2 / Math.sqrt(36 + 4);
        assertTrue(cosAtCentre < 0.35);
        assertEquals(1, integrate(light, p, new Vector3D(-6, 2, 0), 0.2, LightHits.parallelogram(p, corner, a, b)), 2e-3);
    }

    /** Close under a rectangle: it covers 4.60 of the hemisphere's 2 pi sr, the cosines at the light run down to 0.18. */
    @Test
    void aRectangleCloseUpIntegratesToOne() {
        Point3D corner = new Point3D(-1, 2, -1);
        Vector3D a = new Vector3D(0, 0, 2);
        Vector3D b = new Vector3D(2, 0, 0);
        AreaLight light = AreaLight.rectangle(corner, a, b, 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(0.2, 1.7, 0.1);
        assertEquals(1, integrate(light, p, Vector3D.UP, 7, LightHits.parallelogram(p, corner, a, b)), 3e-3);
    }

    /** A 1 x 1 rectangle 2000 away covers 2.5e-7 sr and is nearly as far everywhere: sampled by area. */
    @Test
    void aSmallFarRectangleIntegratesToOne() {
        Point3D corner = new Point3D(-0.5, 2000, -0.5);
        Vector3D a = new Vector3D(0, 0, 1);
        Vector3D b = new Vector3D(1, 0, 0);
        AreaLight light = AreaLight.rectangle(corner, a, b, 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(300, 0, 0);
        assertEquals(1, integrate(light, p, new Vector3D(-300, 2000, 0), 3e-4, LightHits.parallelogram(p, corner, a, b)), 2e-3);
    }

    /** A parallelogram that is not a rectangle is sampled by area. */
    @Test
    void aParallelogramIntegratesToOne() {
        Point3D corner = new Point3D(-1, 2, -1);
        Vector3D a = new Vector3D(0, 0, 2);
        Vector3D b = new Vector3D(2, 0, 0.8);
        AreaLight light = AreaLight.rectangle(corner, a, b, 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(3, 0, 0.5);
        assertEquals(1, integrate(light, p, new Vector3D(-3, 2, 0.5), 0.8, LightHits.parallelogram(p, corner, a, b)), 2e-3);
    }

    @Test
    void aDiskSeenAtAGrazingAngleIntegratesToOne() {
        Point3D center = new Point3D(0, 2, 0);
        AreaLight light = AreaLight.disk(center, new Vector3D(0, -1, 0), 1, 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(5, 0, 1);
        assertEquals(1, integrate(light, p, new Vector3D(-5, 2, -1), 0.25, LightHits.disk(p, center, new Vector3D(0, -1, 0), 1)), 2e-3);
    }

    /**
     * A sphere sampled over the cone it fills: every sample reaches the cap facing the point, so
     * the density integrates to 1 over it (sampled over its whole area, as before, only the share
     * (1 - r / D) / 2 of it could). Near it the cosines at the light run from 1 at the centre of the
     * cap to 0 at its rim; far away the cone is 1e-3 across.
     */
    @ParameterizedTest
    @ValueSource(doubles = {1.6, 1000})
    void aSphereIntegratesToOneOverItsVisibleCap(double distance) {
        double r = 1;
        Point3D center = new Point3D(0, 0, 0);
        AreaLight light = AreaLight.sphere(center, r, 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(distance, 0, 0);
        double halfWidth = 1.05 * r / Math.sqrt(distance * distance - r * r);
        assertEquals(1, integrate(light, p, new Vector3D(-1, 0, 0), halfWidth, LightHits.sphere(p, center, r)), 3e-3);
    }
}
