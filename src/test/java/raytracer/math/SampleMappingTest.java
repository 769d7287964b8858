package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SampleMappingTest {
    private static final int GRID = 400;

    @Test
    void diskMapStaysInTheDiskAndPreservesArea() {
        MutableVec3 p = new MutableVec3();
        int inner = 0;
        for (int i = 0; i < GRID; i++) {
            for (int j = 0; j < GRID; j++) {
                SampleMapping.toUnitDisk((i + 0.5) / GRID, (j + 0.5) / GRID, p);
                double r2 = p.x * p.x + p.y * p.y;
                assertTrue(r2 <= 1 + 1e-12);
                if (r2 < 0.25) {
                    inner++;
                }
            }
        }
        // area preserving: the disk of radius 1/2 holds a quarter of the samples
        assertEquals(0.25, (double) inner / (GRID * GRID), 2e-3);
    }

    @Test
    void hemisphereMapHasTheMeanCosineOfTheCosinePowerLobe() {
        MutableVec3 w = new MutableVec3();
        for (double e : new double[] {0, 1, 10, 1000}) {
            double sum = 0;
            for (int i = 0; i < GRID; i++) {
                for (int j = 0; j < GRID; j++) {
                    SampleMapping.toHemisphere((i + 0.5) / GRID, (j + 0.5) / GRID, e, w);
                    assertEquals(1, w.length(), 1e-12);
                    assertTrue(w.z >= 0);
                    sum += w.z;
                }
            }
            // E[cos] under the density (e+1)/(2 pi) cos^e is (e+1)/(e+2)
            assertEquals((e + 1) / (e + 2), sum / (GRID * GRID), 1e-3, "exponent " + e);
        }
    }

    /**
     * Around any unit axis the mapping is the +z one turned: unit directions whose cosine with the
     * axis is the z of the +z mapping for the same sample, so the density is unchanged.
     */
    @Test
    void hemisphereAroundAnAxisIsTheZMappingTurned() {
        java.util.SplittableRandom random = new java.util.SplittableRandom(9);
        MutableVec3 axis = new MutableVec3();
        MutableVec3 turned = new MutableVec3();
        MutableVec3 plain = new MutableVec3();
        for (int i = 0; i < 20_000; i++) {
            axis.set(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1)).normalize();
            if (i % 3 == 0) {
                axis.set(i % 2 == 0 ? 1 : -1, 0, 0); // the frame's other helper axis
            }
            double u = random.nextDouble();
            double v = random.nextDouble();
            double e = i % 2 == 0 ? 1 : 50;
            SampleMapping.toHemisphere(u, v, e, axis.x, axis.y, axis.z, turned);
            SampleMapping.toHemisphere(u, v, e, plain);
            assertEquals(1, turned.length(), 1e-12);
            assertEquals(plain.z, turned.dot(axis), 1e-12);
        }
    }

    @Test
    void hemispherePdfIntegratesToOne() {
        for (double e : new double[] {0, 1, 20, 500}) {
            // integral over the hemisphere: int_0^{pi/2} pdf(cos t) 2 pi sin t dt, midpoint rule
            int steps = 200_000;
            double dt = (Math.PI / 2) / steps;
            double sum = 0;
            for (int i = 0; i < steps; i++) {
                double t = (i + 0.5) * dt;
                sum += SampleMapping.hemispherePdf(Math.cos(t), e) * 2 * Math.PI * Math.sin(t) * dt;
            }
            assertEquals(1, sum, 1e-4, "exponent " + e);
        }
    }
}
