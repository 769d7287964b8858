package raytracer.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;

/** The registry of named types: order, families kept apart, names registered once, and the built-in types in it. */
class RegistryTest {
    private static final Sampler NOTHING = (n, rng, xs, ys) -> { };

    @Test
    void namesAreListedInTheOrderTheyWereRegistered() {
        Registry registry = Registry.of(List.of(r -> {
            r.sampler("b", () -> NOTHING);
            r.sampler("a", () -> NOTHING);
        }, r -> r.sampler("c", () -> NOTHING)));
        assertEquals(List.of("b", "a", "c"), registry.samplers().names());
        assertSame(NOTHING, registry.samplers().find("a").orElseThrow().make().get());
        assertTrue(registry.samplers().find("d").isEmpty());
    }

    @Test
    void aNameIsRegisteredOncePerFamily() {
        Registration sphereLight = r -> r.light("sphere", Set.of(), p -> null);
        Registration sphereObject = r -> r.object("sphere", Set.of("center"), p -> null);
        Registry both = Registry.of(List.of(sphereLight, sphereObject));
        assertEquals(List.of("sphere"), both.lights().names(), "a light and an object may share a name");
        assertEquals(Set.of("center"), both.objects().find("sphere").orElseThrow().keys());
        IllegalStateException twice = assertThrows(IllegalStateException.class, () -> Registry.of(List.of(sphereLight, sphereLight)));
        assertTrue(twice.getMessage().startsWith("light type 'sphere' is registered twice; the second time by raytracer.core.RegistryTest"),
                   twice.getMessage());
    }

    @Test
    void aTypeNeedsANameAndAWayToMakeIt() {
        assertThrows(IllegalArgumentException.class, () -> Registry.of(List.of(r -> r.texture(" ", Set.of(), p -> null))));
        assertThrows(IllegalArgumentException.class, () -> Registry.of(List.of(r -> r.texture("marble", Set.of(), null))));
    }

    @Test
    void theKeysOfAFamilyAndWhoseTheyAre() {
        Registry registry = Registry.of(List.of(r -> {
            r.filter("box", Set.of(), p -> PixelFilter.BOX);
            r.filter("gaussian", Set.of("filter-stddev"), p -> PixelFilter.BOX);
            r.filter("tent", Set.of("filter-radius"), p -> PixelFilter.BOX);
        }));
        assertEquals(Set.of("filter-stddev", "filter-radius"), registry.filters().keys());
        assertEquals("tent", registry.filters().withKey("filter-radius").orElseThrow().name());
    }

    /** The built-in types register as any other: the readers and options find them here (and any a student adds). */
    @Test
    void theStandardRegistryHoldsTheBuiltInTypes() {
        Registry standard = Registry.standard();
        assertEquals(List.of("regular", "random", "jittered", "n-rooks", "multi-jittered", "correlated-multi-jittered", "hammersley",
                             "sobol"), standard.samplers().names().subList(0, 8), "the book's patterns first, in the order --help lists them");
        assertEquals(List.of("box", "gaussian"), standard.filters().names().subList(0, 2));
        assertEquals(List.of("auto", "list", "median", "sah"), standard.accelerations().names().subList(0, 4));
        assertTrue(standard.cameras().names().containsAll(List.of("pinhole", "thin-lens", "orthographic")));
        assertTrue(standard.lights().names().containsAll(List.of("point", "directional", "rectangle", "disk", "sphere")));
        assertEquals("constant", standard.ambients().names().get(0));
        assertTrue(standard.objects().names().containsAll(List.of("sphere", "plane", "box", "cylinder", "triangle", "mesh")));
        assertTrue(standard.materials().names().containsAll(List.of("matte", "phong", "reflective", "dielectric", "thin-dielectric", "glossy",
                                                                    "ward", "ward-duer", "blinn-phong")));
        assertTrue(standard.textures().names().containsAll(List.of("checker", "constant", "image")));
        assertSame(standard, Registry.standard(), "made once");
    }

    @Test
    void noParametersGiveEveryDefault() throws ParameterException {
        Parameters none = Parameters.NONE;
        assertEquals(1.5, none.number("filter-radius", 1.5, 0.5, true));
        assertEquals(7, none.integer("samples", 7, 1, 10));
        assertEquals(RGBColor.WHITE, none.color("color", RGBColor.WHITE));
        assertEquals(Point3D.ORIGIN, none.point("center", Point3D.ORIGIN));
        assertEquals("x", none.string("preset", "x"));
        assertTrue(none.bool("closed", true) && !none.has("closed"));
        assertEquals("needs the key 'position'", assertThrows(ParameterException.class, () -> none.requiredPoint("position")).getMessage());
    }
}
