package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.Factory;
import raytracer.core.Plugins;
import raytracer.core.Registry;
import raytracer.math.Point3D;

/**
 * The scene reader finds every type in the registry, and a registered type's values are read,
 * checked and reported as the built-in types' are: what a student's registration relies on.
 */
class RegisteredTypesTest {
    private static final String BASE = "image: {width: 4, height: 3}\ncamera: {eye: [0, 0, 5], look-at: [0, 0, 0]}\n";

    private static String error(String yaml) {
        return assertThrows(SceneException.class, () -> SceneLoader.load("s.yaml", yaml)).getMessage();
    }

    private static String allowed(Plugins<?> family) {
        return "; allowed: " + String.join(", ", new TreeSet<>(family.names()));
    }

    /** An unknown type's message lists the registry's names, sorted: the readers have no list of their own. */
    @Test
    void anUnknownTypeListsTheRegisteredNames() {
        Registry r = Registry.standard();
        assertEquals("s.yaml:3:17: unknown light type 'laser'" + allowed(r.lights()), error(BASE + "lights: [{type: laser}]\n"));
        assertEquals("s.yaml:3:18: unknown object type 'teapot'" + allowed(r.objects()), error(BASE + "objects: [{type: teapot}]\n"));
        assertEquals("s.yaml:1:16: unknown camera type 'fisheye'" + allowed(r.cameras()), error("camera: {type: fisheye}\n"));
        assertEquals("s.yaml:1:23: unknown material type 'velvet'" + allowed(r.materials()), error("materials: {m: {type: velvet}}\n"));
        assertEquals("s.yaml:1:46: unknown texture type 'marble'" + allowed(r.textures()),
                     error("materials: {m: {type: matte, texture: {type: marble}}}\n"));
        assertEquals("s.yaml:1:18: unknown sampler 'poisson'; allowed: " + String.join(", ", r.samplers().names()),
                     error("image: {sampler: poisson}\n"));
        assertEquals("s.yaml:1:17: unknown filter 'mitchell'; allowed: " + String.join(", ", r.filters().names()),
                     error("image: {filter: mitchell}\n"));
    }

    @Test
    void aFiltersKeyWithAnotherFilterNamesTheFilterItIsFor() {
        assertEquals("s.yaml:1:37: 'filter-stddev' in image is for filter: gaussian, not box", error("image: {filter: box, filter-stddev: 1}\n"));
        assertEquals("s.yaml:1:24: 'filter-stddev' in image is for filter: gaussian, not box", error("image: {filter-stddev: 1}\n"));
    }

    /** The ambient section's type is a key only when there is a type to choose, so that its keys read as they always have. */
    @Test
    void theAmbientsTypeIsAKeyOnceThereIsAChoice() throws SceneException {
        List<String> ambients = Registry.standard().ambients().names();
        if (ambients.size() == 1) {
            assertEquals("s.yaml:1:44: unknown key 'type' in ambient; allowed: color, radiance",
                         error("ambient: {radiance: 0.2, color: [1, 1, 1], type: constant}\n"));
        } else {
            assertEquals("s.yaml:1:17: unknown ambient type 'sky'" + allowed(Registry.standard().ambients()),
                         error("ambient: {type: sky}\n"));
            SceneLoader.load("s.yaml", "ambient: {type: constant, radiance: 0.2}\nobjects: []\n");
        }
        assertEquals("s.yaml:1:21: 'radiance' in ambient must be at least 0, got -1", error("ambient: {radiance: -1}\n"));
    }

    private static final Set<String> SPOT_KEYS = Set.of("type", "position", "angle");

    /** A type a registration adds, as a student writes it. */
    private static final Factory<Point3D> SPOT = p -> {
        double angle = p.number("angle", 30, 0, true);
        if (angle >= 180) {
            throw p.error("angle", "a cone of " + angle + " degrees is no cone");
        }
        if (angle == 90) {
            throw new IllegalArgumentException("a flat cone");
        }
        return p.requiredPoint("position");
    };

    /** The spot of {@code yaml}, made as a reader makes a registered type. */
    private static Point3D spot(String yaml) throws SceneException {
        Source source = new Source("s.yaml", null);
        Node node = SceneLoader.root(source, yaml);
        return new YamlParameters(new YamlObject(source, node, "spot light", SPOT_KEYS), null).make(SPOT, node, "spot: ");
    }

    private static String refused(String yaml) {
        return assertThrows(SceneException.class, () -> spot(yaml)).getMessage();
    }

    /** A registered type's values are checked, and its errors name the file, line, column and key, as the built-in types' do. */
    @Test
    void aRegisteredTypesValuesAreCheckedAsTheBuiltInTypes() throws SceneException {
        assertEquals(new Point3D(1, 2, 3), spot("{type: spot, position: [1, 2, 3]}"));
        assertEquals("s.yaml:1:21: 'angle' in spot light must be greater than 0, got -3", refused("{type: spot, angle: -3}"));
        assertEquals("s.yaml:1:21: a cone of 200.0 degrees is no cone", refused("{type: spot, angle: 200}"));
        assertEquals("s.yaml:1:1: spot: a flat cone", refused("{type: spot, angle: 90}"));
        assertEquals("s.yaml:1:1: spot light needs the key 'position'", refused("{type: spot}"));
        assertEquals("s.yaml:1:14: unknown key 'angel' in spot light; allowed: angle, position, type", refused("{type: spot, angel: 3}"));
    }
}
