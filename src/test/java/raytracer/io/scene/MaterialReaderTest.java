package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.core.Material;
import raytracer.materials.ThinDielectric;

/** The materials of a scene file: the thin sheet of glass, its keys and its errors. */
class MaterialReaderTest {
    private static final String OBJECTS = "objects:\n  - {type: sphere, center: [0, 0, 0], radius: 1, material: pane}\n";

    private static Material pane(String material) throws SceneException {
        return SceneLoader.load("s.yaml", "materials:\n  pane: " + material + "\n" + OBJECTS).world().materials().stream()
            .filter(m -> m.name().equals("pane")).findFirst().orElseThrow();
    }

    private static String error(String material) {
        SceneException e = assertThrows(SceneException.class, () -> pane(material));
        assertEquals(1, e.getMessage().lines().count(), "one line: " + e.getMessage());
        return e.getMessage();
    }

    @Test
    void aThinDielectricHasAnIndexAndAHighlight() throws SceneException {
        assertEquals(1.5, assertInstanceOf(ThinDielectric.class, pane("{type: thin-dielectric}")).ior(), 0, "the default index");
        assertEquals(1.33, assertInstanceOf(ThinDielectric.class, pane("{type: thin-dielectric, ior: 1.33, ks: 0.5, exponent: 200}"))
            .ior(), 0);
    }

    @Test
    void aThinDielectricHasNoInsideToAbsorbIn() {
        assertEquals("s.yaml:2:33: unknown key 'absorption' in thin-dielectric material 'pane'; allowed: exponent, ior, ks, "
                     + "reflection-map, type", error("{type: thin-dielectric, absorption: [1, 1, 1]}"));
        // the list of types, not its whole text: a student's registered type (docs/teaching.md) joins it
        String unknown = error("{type: thin-glass}");
        assertTrue(unknown.startsWith("s.yaml:2:16: unknown material type 'thin-glass'; allowed: blinn-phong, "), unknown);
        assertTrue(unknown.contains(", dielectric, glossy, matte, phong, reflective, thin-dielectric, ward, ward-duer"), unknown);
        assertEquals("s.yaml:2:38: 'ior' in thin-dielectric material 'pane' must be greater than 0, got 0",
                     error("{type: thin-dielectric, ior: 0}"));
    }
}
