package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.AreaLight;
import raytracer.math.MutableVec3;

/**
 * A rectangle light's {@code sampling}: auto (by solid angle if an object lies near it, else by
 * area), solid-angle or area, whatever lies near; the density of a sample tells which (1 / area,
 * here 1 / 4, by area). The floor 0.5 below the light lies near it, so auto samples by solid angle.
 */
class LightSamplingKeyTest {
    private static World load(String light) throws SceneException {
        World world = SceneLoader.load("light.yaml", """
            image: {width: 1, height: 1}
            camera: {eye: [0, 5, 5], look-at: [0, 0, 0]}
            lights:
              - {type: rectangle, corner: [-1, 4, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 2], visible: false%s}
            objects:
              - {type: plane, point: [0, 3.5, 0], normal: [0, 1, 0]}
            """.formatted(light)).world();
        world.prepare();
        return world;
    }

    private static double pdf(World world) {
        AreaLight light = (AreaLight) world.lights()[world.lights().length - 1];
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.hitPoint.set(0.5, 3.5, 0.2);
        sr.normal.set(0, 1, 0);
        light.sample(sr, 0.3, 0.7, new MutableVec3());
        return light.pdf(sr);
    }

    @Test
    void eachChoiceSamplesAsItSays() throws SceneException {
        assertNotEquals(0.25, pdf(load("")), "auto, near the floor: by solid angle");
        assertNotEquals(0.25, pdf(load(", sampling: solid-angle")));
        assertEquals(0.25, pdf(load(", sampling: area")), 0);
    }

    @Test
    void aBadValueNamesTheKeyAndTheValuesAllowed() {
        SceneException e = assertThrows(SceneException.class, () -> load(", sampling: cone"));
        assertTrue(e.getMessage().contains("'sampling'") && e.getMessage().contains("auto, solid-angle, area")
                   && e.getMessage().contains("'cone'"), e.getMessage());
    }

    @Test
    void aParallelogramCannotBeSampledBySolidAngle() {
        SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load("light.yaml", """
            image: {width: 1, height: 1}
            camera: {eye: [0, 5, 5], look-at: [0, 0, 0]}
            lights:
              - {type: rectangle, corner: [-1, 4, -1], edge-a: [2, 0, 0], edge-b: [1, 0, 2], sampling: solid-angle}
            objects:
              - {type: plane, point: [0, 3.5, 0], normal: [0, 1, 0]}
            """));
        assertTrue(e.getMessage().contains("sampled by area only"), e.getMessage());
    }
}
