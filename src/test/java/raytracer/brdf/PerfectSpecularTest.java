package raytracer.brdf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/** The mirror's sample_f: the law of reflection and the weight kr cr, whatever the sample. */
class PerfectSpecularTest {

    @Test
    void samplesTheMirrorDirectionWithWeightKrCr() {
        PerfectSpecular mirror = new PerfectSpecular(0.8, new RGBColor(1, 0.5, 0.25));
        SplittableRandom random = new SplittableRandom(17);
        MutableVec3 wi = new MutableVec3();
        MutableRgb weight = new MutableRgb();
        for (int i = 0; i < 10_000; i++) {
            ShadeRec sr = i % 100 == 0
                ? Hits.withNormal(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1))
                : Hits.withNormal(0, 0, 1);
            MutableVec3 n = sr.normal;
            MutableVec3 wo = new MutableVec3().set(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1)).normalize();
            if (n.dot(wo) <= 0) {
                wo.negate();
            }
            assertTrue(mirror.sampleF(sr, wo, random.nextDouble(), random.nextDouble(), wi, weight));
            // the law of reflection: equal angles, in the plane of n and wo, on the other side of n
            assertEquals(1, wi.length(), 1e-12);
            assertEquals(n.dot(wo), n.dot(wi), 1e-12, "equal angles");
            double[] sum = {wi.x + wo.x, wi.y + wo.y, wi.z + wo.z};
            double along = sum[0] * n.x + sum[1] * n.y + sum[2] * n.z;
            for (int k = 0; k < 3; k++) {
                double component = k == 0 ? n.x : k == 1 ? n.y : n.z;
                assertEquals(along * component, sum[k], 1e-12, "wi + wo lies along n");
            }
            assertEquals(0.8, weight.r, 1e-15);
            assertEquals(0.4, weight.g, 1e-15);
            assertEquals(0.2, weight.b, 1e-15);
        }
    }

    @Test
    void aDeltaHasNoValueNoDensityAndNoAmbientResponse() {
        PerfectSpecular mirror = new PerfectSpecular(1, RGBColor.WHITE);
        ShadeRec sr = Hits.withNormal(0, 0, 1);
        MutableVec3 wo = Hits.direction(30, 0);
        MutableVec3 wi = Hits.direction(30, 180); // the mirror direction itself
        MutableRgb out = new MutableRgb().set(1, 1, 1);
        mirror.f(sr, wo, wi, out);
        assertEquals(0, out.r + out.g + out.b);
        assertEquals(0, mirror.pdf(sr, wo, wi));
        out.set(1, 1, 1);
        mirror.rho(sr, wo, out);
        assertEquals(0, out.r + out.g + out.b);
    }
}
