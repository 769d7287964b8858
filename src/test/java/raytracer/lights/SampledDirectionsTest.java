package raytracer.lights;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.MutableVec3;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.samplers.MultiJittered;

/**
 * The directions a light's sampling draws are distributed as its {@code directionPdf} says: a
 * histogram of 400,000 sampled directions, binned on the gnomonic plane one unit from the point
 * (16 x 16 bins across the light), against the counts the density gives (its integral over each
 * bin by the midpoint rule on 40 x 40 cells, the light found by plain geometry, {@link LightHits}),
 * by Pearson's chi-square over the bins that expect at least 20 samples. With that many degrees
 * of freedom k the statistic is about normal, mean k and standard deviation sqrt(2 k); the test
 * asks for less than k + 6 sqrt(2 k) (a chance near 1e-8 of failing when the density is right; the
 * seed is fixed). A sampling map that were not area-preserving, or a density that did not match it,
 * would be off by far more in the bins where they differ.
 */
class SampledDirectionsTest {
    private static final int SAMPLES = 400_000;
    private static final int BINS = 16;
    private static final int CELLS = 40;

    private static ShadeRec shadeRecAt(Point3D p) {
        World world = new World(new ViewPlane(1, 1, 1, new MultiJittered(), 0, 1),
            new Orthographic(new Point3D(0, 5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.hitPoint.set(p.x(), p.y(), p.z());
        return sr;
    }

    /** The chi-square statistic over k bins and k itself, after checking every sample landed in the grid. */
    private static void assertHistogramMatches(String name, AreaLight light, Point3D p, Vector3D towards, double halfWidth,
                                               LightHits g) {
        Vector3D w = towards.normalize();
        Vector3D helper = Math.abs(w.x()) < 0.9 ? new Vector3D(1, 0, 0) : new Vector3D(0, 1, 0);
        Vector3D e1 = helper.cross(w).normalize();
        Vector3D e2 = w.cross(e1);
        double binWidth = 2 * halfWidth / BINS;
        // observed: the samples' directions, on the plane p + w + x e1 + y e2
        ShadeRec sr = shadeRecAt(p);
        MutableVec3 wi = new MutableVec3();
        long[] observed = new long[BINS * BINS];
        SplittableRandom random = new SplittableRandom(3);
        for (int i = 0; i < SAMPLES; i++) {
            light.sample(sr, random.nextDouble(), random.nextDouble(), wi);
            double along = wi.x * w.x() + wi.y * w.y() + wi.z * w.z();
            double x = (wi.x * e1.x() + wi.y * e1.y() + wi.z * e1.z()) / along;
            double y = (wi.x * e2.x() + wi.y * e2.y() + wi.z * e2.z()) / along;
            int bx = (int) Math.floor((x + halfWidth) / binWidth);
            int by = (int) Math.floor((y + halfWidth) / binWidth);
            assertTrue(along > 0 && bx >= 0 && by >= 0 && bx < BINS && by < BINS, name + ": a sample outside the light's directions");
            observed[by * BINS + bx]++;
        }
        // expected: SAMPLES times the density's integral over each bin
        double h = binWidth / CELLS;
        double chi2 = 0;
        int bins = 0;
        long left = 0;
        for (int by = 0; by < BINS; by++) {
            for (int bx = 0; bx < BINS; bx++) {
                double integral = 0;
                for (int i = 0; i < CELLS; i++) {
                    double x = -halfWidth + bx * binWidth + (i + 0.5) * h;
                    for (int j = 0; j < CELLS; j++) {
                        double y = -halfWidth + by * binWidth + (j + 0.5) * h;
                        double dx = w.x() + x * e1.x() + y * e2.x();
                        double dy = w.y() + x * e1.y() + y * e2.y();
                        double dz = w.z() + x * e1.z() + y * e2.z();
                        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                        double[] hit = g.hit(dx / len, dy / len, dz / len);
                        if (hit != null) {
                            double cosAlpha = 1 / len;
                            integral += light.directionPdf(p.x(), p.y(), p.z(), hit[0], hit[1]) * cosAlpha * cosAlpha * cosAlpha * h * h;
                        }
                    }
                }
                double expected = SAMPLES * integral;
                long seen = observed[by * BINS + bx];
                if (expected >= 20) {
                    chi2 += (seen - expected) * (seen - expected) / expected;
                    bins++;
                } else {
                    left += seen;
                }
            }
        }
        double limit = bins + 6 * Math.sqrt(2.0 * bins);
        assertTrue(bins >= 40, name + ": the light spans enough bins: " + bins);
        assertTrue(left < 0.01 * SAMPLES, name + ": samples where the density expects almost none: " + left);
        assertTrue(chi2 < limit, name + ": chi-square " + chi2 + " over " + bins + " bins, limit " + limit);
    }

    @Test
    void aRectangleCloseUpIsSampledAsItsDensitySays() {
        Point3D corner = new Point3D(-1, 2, -1);
        Vector3D a = new Vector3D(0, 0, 2);
        Vector3D b = new Vector3D(2, 0, 0);
        Point3D p = new Point3D(0.2, 1.7, 0.1);
        assertHistogramMatches("rectangle close up", AreaLight.rectangle(corner, a, b, 1, RGBColor.WHITE, 1), p, Vector3D.UP, 6,
                               LightHits.parallelogram(p, corner, a, b));
    }

    @Test
    void aRectangleAtAGrazingAngleIsSampledAsItsDensitySays() {
        Point3D corner = new Point3D(-1, 2, -1);
        Vector3D a = new Vector3D(0, 0, 2);
        Vector3D b = new Vector3D(2, 0, 0);
        Point3D p = new Point3D(6, 0, 0);
        assertHistogramMatches("rectangle at a grazing angle", AreaLight.rectangle(corner, a, b, 1, RGBColor.WHITE, 1), p,
                               new Vector3D(-6, 2, 0), 0.2, LightHits.parallelogram(p, corner, a, b));
    }

    @Test
    void aParallelogramIsSampledAsItsDensitySays() {
        Point3D corner = new Point3D(-1, 2, -1);
        Vector3D a = new Vector3D(0, 0, 2);
        Vector3D b = new Vector3D(2, 0, 0.8);
        Point3D p = new Point3D(0.5, 1.2, 0.5);
        assertHistogramMatches("parallelogram", AreaLight.rectangle(corner, a, b, 1, RGBColor.WHITE, 1), p, Vector3D.UP, 3.2,
                               LightHits.parallelogram(p, corner, a, b));
    }

    @Test
    void aDiskIsSampledAsItsDensitySays() {
        Point3D center = new Point3D(0, 2, 0);
        Vector3D n = new Vector3D(0, -1, 0);
        Point3D p = new Point3D(0.8, 1.4, 0);
        assertHistogramMatches("disk", AreaLight.disk(center, n, 1, 1, RGBColor.WHITE, 1), p, Vector3D.UP, 3.1,
                               LightHits.disk(p, center, n, 1));
    }

    @Test
    void aSphereCloseUpIsSampledAsItsDensitySays() {
        Point3D center = new Point3D(0, 0, 0);
        Point3D p = new Point3D(1.3, 0.2, 0);
        Vector3D towards = new Vector3D(-1.3, -0.2, 0);
        double d = Math.sqrt(1.3 * 1.3 + 0.2 * 0.2);
        assertHistogramMatches("sphere close up", AreaLight.sphere(center, 1, 1, RGBColor.WHITE, 1), p, towards,
                               1.02 / Math.sqrt(d * d - 1), LightHits.sphere(p, center, 1));
    }
}
