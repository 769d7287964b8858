package raytracer.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.math.MutableRgb;

/**
 * The ray-tree policy on hand-worked numbers: path weights multiply down the tree, a branch is
 * worth tracing while some channel of its weight reaches the cutoff, light samples shrink with the
 * weight, negligibility is judged in display units, and the passes gate the first hit only.
 */
class RayTreePolicyTest {

    private static RayTreePolicy policy(double cutoff, double exposure, ShadingPass pass) {
        return new RayTreePolicy(new RayTreeSettings(pass, cutoff), exposure, 6);
    }

    @Test
    void branchWeightsMultiplyDownTheTreeAgainstTheCutoff() {
        RayTreePolicy p = policy(0.01, 1, ShadingPass.FULL);
        assertEquals(1, p.weight(0), "a camera ray weighs 1");
        assertTrue(p.recordBranchWeight(0, 0.5, 0.2, 0.1));
        assertEquals(0.5, p.weight(1));
        // 0.5 x 0.03 = 0.015 in red: still worth tracing, though green and blue are below
        assertTrue(p.recordBranchWeight(1, 0.03, 0.03, 0.03));
        assertEquals(0.015, p.weight(2), 1e-15);
        // 0.015 x 0.5 = 0.0075 in every channel: below 0.01
        assertFalse(p.recordBranchWeight(2, 0.5, 0.5, 0.5));
        assertEquals(0.0075, p.weight(3), 1e-15);
        // a sibling branch from depth 1 overwrites the record of depth 2
        assertTrue(p.recordBranchWeight(1, 1, 0, 0));
        assertEquals(0.5, p.weight(2));
    }

    @Test
    void lightSamplesShrinkWithThePathWeightOnlyWhenTheCutoffIsOn() {
        RayTreePolicy on = policy(1e-3, 1, ShadingPass.FULL);
        assertEquals(16, on.lightSamples(0, 16), "camera rays take every sample");
        on.recordBranchWeight(0, 0.3, 0.3, 0.3);
        assertEquals(4, on.lightSamples(1, 16), "floor(16 x 0.3)");
        on.recordBranchWeight(1, 0.01, 0.01, 0.01);
        assertEquals(1, on.lightSamples(2, 16), "at least one");
        RayTreePolicy off = policy(0, 1, ShadingPass.FULL);
        off.recordBranchWeight(0, 0.3, 0.3, 0.3);
        assertEquals(16, off.lightSamples(1, 16));
    }

    @Test
    void negligibleRadianceIsJudgedAfterTheExposure() {
        // cutoff 0.01 at exposure 4: radiance below 0.0025 in every channel, times the path weight
        RayTreePolicy p = policy(0.01, 4, ShadingPass.FULL);
        assertTrue(p.negligible(0, 0.0024, 0.001, 0));
        assertFalse(p.negligible(0, 0.0026, 0, 0));
        p.recordBranchWeight(0, 0.5, 0.5, 0.5);
        assertTrue(p.negligible(1, 0.0049, 0, 0));
        assertFalse(p.negligible(1, 0, 0, 0.0051));
        assertFalse(policy(0, 1, ShadingPass.FULL).negligible(0, 0, 0, 0), "cutoff 0 traces everything");
    }

    @Test
    void passesGateTheFirstHitAndMagentaReplacesItsReflectedEnvironment() {
        Background own = (ray, out) -> out.set(0, 1, 0);
        RayTreePolicy direct = policy(0, 1, ShadingPass.DIRECT);
        assertTrue(direct.showsDirect(0));
        assertFalse(direct.showsReflection(0));
        assertFalse(direct.showsRefraction(0));
        assertTrue(direct.showsReflection(1), "deeper hits are shaded in full");
        RayTreePolicy magenta = policy(0, 1, ShadingPass.MAGENTA_REFLECTION);
        MutableRgb seen = new MutableRgb();
        magenta.reflectedEnvironment(0, own).radiance(null, seen);
        assertEquals(1, seen.r);
        assertEquals(0, seen.g);
        assertEquals(1, seen.b);
        assertSame(own, magenta.reflectedEnvironment(1, own));
        assertNull(policy(0, 1, ShadingPass.FULL).reflectedEnvironment(0, null), "the scene's background");
        assertFalse(policy(0, 1, ShadingPass.NO_FRESNEL).angleDependent());
        assertTrue(magenta.angleDependent());
    }
}
