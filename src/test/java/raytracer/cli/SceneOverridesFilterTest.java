package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Pinhole;
import raytracer.core.PixelFilter;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.samplers.Samplers;

/** --filter replaces the scene's filter by name; naming the scene's own keeps its width. */
class SceneOverridesFilterTest {
    @Test
    void theSameFilterKeepsTheScenesStandardDeviation() {
        assertEquals(1.5, filterAfter(PixelFilter.gaussian(1.5), PixelFilter.named("gaussian")).stddev());
        assertEquals(PixelFilter.BOX, filterAfter(PixelFilter.gaussian(1.5), PixelFilter.BOX));
        assertEquals(0.5, filterAfter(PixelFilter.BOX, PixelFilter.named("gaussian")).stddev());
        assertEquals(1.5, filterAfter(PixelFilter.gaussian(1.5), null).stddev(), "no option: the scene's");
    }

    private static PixelFilter filterAfter(PixelFilter scene, PixelFilter option) {
        ViewPlane vp = new ViewPlane(4, 4, 1, Samplers.byName("regular"), 1, 1, scene);
        World world = new World(vp, new Pinhole(new Point3D(0, 0, 5), new Point3D(0, 0, 0), new Vector3D(0, 1, 0), 40),
                                new Ambient(0, RGBColor.WHITE));
        new SceneOverrides(null, null, null, null, option, null, null, null, null).applyTo(world);
        return world.viewPlane().filter();
    }
}
