package raytracer.btdf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import raytracer.cameras.Pinhole;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/**
 * The transmitter's sample_f against Snell's law and the Fresnel equations written with angles
 * (Hecht, Optics, eq. 4.42 and 4.43: R_s = sin^2(i - t) / sin^2(i + t),
 * R_p = tan^2(i - t) / tan^2(i + t)), independent of the cosine forms in math.Fresnel.
 */
class PerfectTransmitterTest {

    /** A hit on the plane z = 0, normal +z towards wo, entering the medium or leaving it. */
    private static ShadeRec hit(boolean frontFace) {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 1, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.normal.set(0, 0, 1);
        sr.frontFace = frontFace;
        return sr;
    }

    @ParameterizedTest
    @CsvSource({"1.5, true, 0", "1.5, true, 30", "1.5, true, 60", "1.5, true, 89", "1.33, true, 45",
                "1.5, false, 20", "1.5, false, 41", "2.4, false, 24"})
    void refractsBySnellsLawWithWeightOneMinusFresnel(double ior, boolean entering, double degrees) {
        double i = Math.toRadians(degrees);
        ShadeRec sr = hit(entering);
        // wo in the xz plane, degrees from the normal, on the +x side
        MutableVec3 wo = new MutableVec3().set(Math.sin(i), 0, Math.cos(i));
        MutableVec3 wt = new MutableVec3();
        MutableRgb weight = new MutableRgb();
        assertTrue(new PerfectTransmitter(ior).sampleF(sr, wo, wt, weight));
        double etaI = entering ? 1 : ior;
        double etaT = entering ? ior : 1;
        double t = Math.asin(etaI / etaT * Math.sin(i));
        // through the surface, on the far side of the normal, at the angle Snell's law gives
        assertEquals(1, wt.length(), 1e-12);
        assertEquals(-Math.sin(t), wt.x, 1e-12);
        assertEquals(0, wt.y, 1e-15);
        assertEquals(-Math.cos(t), wt.z, 1e-12);
        double r = degrees == 0
            ? Math.pow((etaT - etaI) / (etaT + etaI), 2)
            : 0.5 * (Math.pow(Math.sin(i - t) / Math.sin(i + t), 2) + Math.pow(Math.tan(i - t) / Math.tan(i + t), 2));
        assertEquals(1 - r, weight.r, 1e-12, "1 - R");
        assertEquals(weight.r, weight.g, 0);
        assertEquals(weight.r, weight.b, 0);
    }

    @ParameterizedTest
    @CsvSource({"1.5, 42", "1.5, 80", "2.4, 25"})
    void nothingCrossesPastTheCriticalAngle(double ior, double degrees) {
        assertTrue(Math.sin(Math.toRadians(degrees)) * ior > 1, "past the critical angle asin(1 / ior)");
        ShadeRec sr = hit(false);
        double i = Math.toRadians(degrees);
        MutableRgb weight = new MutableRgb().set(1, 1, 1);
        assertFalse(new PerfectTransmitter(ior).sampleF(sr, new MutableVec3().set(Math.sin(i), 0, Math.cos(i)), new MutableVec3(), weight));
        assertEquals(0, weight.r + weight.g + weight.b);
    }

    @ParameterizedTest
    @CsvSource({"true", "false"})
    void aDeltaHasNoValueAndNoAmbientResponse(boolean entering) {
        ShadeRec sr = hit(entering);
        PerfectTransmitter transmitter = new PerfectTransmitter(1.5);
        MutableVec3 wo = new MutableVec3().set(0, 0, 1);
        MutableRgb out = new MutableRgb().set(1, 1, 1);
        transmitter.f(sr, wo, new MutableVec3().set(0, 0, -1), out);
        assertEquals(0, out.r + out.g + out.b);
        out.set(1, 1, 1);
        transmitter.rho(sr, wo, out);
        assertEquals(0, out.r + out.g + out.b);
    }
}
