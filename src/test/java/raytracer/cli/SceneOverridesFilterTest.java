package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Pinhole;
import raytracer.core.PixelFilter;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.filters.Filters;
import raytracer.filters.Gaussian;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.samplers.Samplers;

/** --filter and --filter-stddev against the scene's filter. */
class SceneOverridesFilterTest {
    @Test
    void theOptionsReplaceTheScenesFilterAsAsked() {
        PixelFilter wide = new Gaussian(1.5);
        assertEquals(wide, filterAfter(wide, FilterChoice.parse(null, null)), "no option: the scene's");
        assertEquals(1.5, ((Gaussian) filterAfter(wide, FilterChoice.parse("gaussian", null))).stddev(), "the same filter keeps the scene's width");
        assertEquals(PixelFilter.BOX, filterAfter(wide, FilterChoice.parse("box", null)));
        assertEquals(0.5, ((Gaussian) filterAfter(PixelFilter.BOX, FilterChoice.parse("gaussian", null))).stddev(), "the default width");
        assertEquals(0.8, ((Gaussian) filterAfter(PixelFilter.BOX, FilterChoice.parse(null, 0.8))).stddev(), "a width alone asks for the Gaussian");
        assertEquals(0.8, ((Gaussian) filterAfter(wide, FilterChoice.parse("gaussian", 0.8))).stddev(), "the given width wins");
    }

    @Test
    void badChoicesSayWhatIsWrong() {
        assertEquals("unknown --filter 'mitchell'; allowed: " + String.join(", ", Filters.names()),
                     assertThrows(IllegalArgumentException.class, () -> FilterChoice.parse("mitchell", null)).getMessage());
        assertEquals("--filter-stddev is for --filter gaussian, not box",
                     assertThrows(IllegalArgumentException.class, () -> FilterChoice.parse("box", 1.0)).getMessage());
        for (double bad : new double[] {0.1, 2.5, Double.NaN}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FilterChoice.parse(null, bad));
            assertEquals("--filter-stddev must be 0.2 to 2.0 pixels, got " + bad, e.getMessage());
        }
    }

    private static PixelFilter filterAfter(PixelFilter scene, FilterChoice option) {
        ViewPlane vp = new ViewPlane(4, 4, 1, Samplers.byName("regular"), 1, 1, scene);
        World world = new World(vp, new Pinhole(new Point3D(0, 0, 5), new Point3D(0, 0, 0), new Vector3D(0, 1, 0), 40),
                                new Ambient(0, RGBColor.WHITE));
        new SceneOverrides(null, null, null, null, option, null, null, null, null).applyTo(world);
        return world.viewPlane().filter();
    }
}
