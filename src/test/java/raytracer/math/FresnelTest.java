package raytracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class FresnelTest {

    @Test
    void normalIncidenceGivesTheClosedForm() {
        for (double n : new double[] {1.33, 1.5, 2.4}) {
            double expected = Math.pow((n - 1) / (n + 1), 2);
            assertEquals(expected, Fresnel.dielectric(1, 1, n), 1e-15);
            assertEquals(expected, Fresnel.dielectric(1, n, 1), 1e-15, "the same from inside");
        }
        assertEquals(0.04, Fresnel.dielectric(1, 1, 1.5), 1e-15);
    }

    @Test
    void pPolarisedReflectanceVanishesAtBrewstersAngle() {
        double n = 1.5;
        double brewster = Math.atan(n);
        assertEquals(0, Fresnel.parallel(Math.cos(brewster), 1, n), 1e-15);
        assertTrue(Fresnel.perpendicular(Math.cos(brewster), 1, n) > 0.1);
        // from inside, Brewster's angle is atan(1/n)
        assertEquals(0, Fresnel.parallel(Math.cos(Math.atan(1 / n)), n, 1), 1e-15);
    }

    @Test
    void totalInternalReflectionPastTheCriticalAngle() {
        double n = 1.5;
        double critical = Math.asin(1 / n);
        assertEquals(1, Fresnel.dielectric(Math.cos(critical + 1e-6), n, 1), 0);
        assertEquals(1, Fresnel.dielectric(Math.cos(Math.toRadians(80)), n, 1), 0);
        assertTrue(Fresnel.dielectric(Math.cos(critical - 1e-3), n, 1) < 1);
        assertTrue(Double.isNaN(Fresnel.cosTransmitted(Math.cos(critical + 1e-6), n, 1)));
    }

    @Test
    void grazingIncidenceReflectsEverythingAndReflectanceGrowsWithAngle() {
        assertEquals(1, Fresnel.dielectric(0, 1, 1.5), 1e-12);
        double previous = 0;
        for (int deg = 0; deg < 90; deg += 5) {
            double r = Fresnel.dielectric(Math.cos(Math.toRadians(deg)), 1, 1.5);
            assertTrue(r >= previous - 1e-15 && r >= 0 && r <= 1, "at " + deg + " degrees: " + r);
            previous = r;
        }
    }

    @Test
    void snellsLawHolds() {
        double n = 1.5;
        for (int deg = 0; deg < 90; deg += 10) {
            double i = Math.toRadians(deg);
            double cosT = Fresnel.cosTransmitted(Math.cos(i), 1, n);
            assertEquals(Math.sin(i), n * Math.sqrt(1 - cosT * cosT), 1e-12);
        }
    }

    @Test
    void schlickMatchesItsEnds() {
        assertEquals(0.5, Fresnel.schlick(0.5, 1), 0);
        assertEquals(1, Fresnel.schlick(0.5, 0), 0);
        assertEquals(0.04, Fresnel.schlick(0.04, 1), 0);
        // Schlick with the f0 of glass stays within 0.002 of the exact curve up to 30 degrees and
        // within 0.04 everywhere (the largest gap, 0.036, is near 85 degrees)
        for (int deg = 0; deg <= 90; deg += 5) {
            double c = Math.cos(Math.toRadians(deg));
            double tolerance = deg <= 30 ? 0.002 : 0.04;
            assertEquals(Fresnel.dielectric(c, 1, 1.5), Fresnel.schlick(0.04, c), tolerance, deg + " degrees");
        }
    }
}
