package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * MTL and OBJ values are range-checked as a scene's YAML values are: before,
 * Kd -5 put negative radiance in the image, Kd or Ke 1e400 parsed as infinity and every sample of
 * the object was dropped, vn 1e300 overflowed the float normal to NaN, all with exit 0. Each is
 * now one error naming the file and line.
 */
class ValueRangeTest {
    @TempDir
    Path dir;

    private static final String TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

    private String errorOfMtl(String mtl) throws IOException {
        Files.writeString(dir.resolve("m.mtl"), "newmtl a\n" + mtl + "\n", StandardCharsets.UTF_8);
        Path obj = Files.writeString(dir.resolve("m.obj"), "mtllib m.mtl\nusemtl a\n" + TRIANGLE + "f 1 2 3\n");
        return assertThrows(ObjException.class, () -> ObjLoader.load(obj, false)).getMessage();
    }

    private String errorOfObj(String lines) throws IOException {
        Path obj = Files.writeString(dir.resolve("o.obj"), TRIANGLE + lines + "\nf 1 2 3\n");
        return assertThrows(ObjException.class, () -> ObjLoader.load(obj, false)).getMessage();
    }

    @Test
    void mtlValuesOutOfRangeAreErrorsWithFileAndLine() throws IOException {
        String at = dir.resolve("m.mtl") + ":2: ";
        assertEquals(at + "Kd must be 3 finite numbers of at least 0, got -5", errorOfMtl("Kd -5"));
        assertEquals(at + "Kd must be 3 finite numbers of at least 0, got 1e400", errorOfMtl("Kd 1 1e400 1"));
        assertEquals(at + "Ks must be 3 finite numbers of at least 0, got -0.5", errorOfMtl("Ks 0.5 -0.5 0.5"));
        assertEquals(at + "Ka must be 3 finite numbers of at least 0, got -1", errorOfMtl("Ka -1 0 0"));
        assertTrue(errorOfMtl("Ke 1e400").startsWith(at + "Ke must be 3 finite numbers of at least 0"), errorOfMtl("Ke 1e400"));
        assertEquals(at + "Ke must be at most 3.40282e+38 (the largest value an image holds), got 1e39",
                     errorOfMtl("Ke 1e39 0 0"));
        assertEquals(at + "Ns must be a finite number of at least 0, got -3", errorOfMtl("Ns -3"));
        assertEquals(at + "d must be a number from 0 to 1, got 2", errorOfMtl("d 2"));
        assertEquals(at + "Tr must be a number from 0 to 1, got -1", errorOfMtl("Tr -1"));
        assertEquals(at + "illum must be a whole number from 0 to 10, got 1e400", errorOfMtl("illum 1e400"));
    }

    /**
     * An index of refraction that is not one (0, negative, infinite) is a warning and the default
     * kept: tinyobjloader takes any Ni without a check, and a library that is read elsewhere
     * should not stop a render here over a value only glass uses.
     */
    @Test
    void anNiThatIsNotAnIndexOfRefractionIsAWarning() throws Exception {
        for (String ni : new String[] {"0", "-1.5", "1e400"}) {
            Files.writeString(dir.resolve("m.mtl"), "newmtl a\nNi " + ni + "\nKd 0.5 0.5 0.5\n", StandardCharsets.UTF_8);
            Path obj = Files.writeString(dir.resolve("m.obj"), "mtllib m.mtl\nusemtl a\n" + TRIANGLE + "f 1 2 3\n");
            ObjModel model = ObjLoader.load(obj, false);
            assertEquals(1.0, model.materials().get(0).ior(), "the default, read as no index (glass takes 1.5)");
            assertEquals(0.5, model.materials().get(0).kd()[0], "the rest of the material is read");
            assertEquals(java.util.List.of(dir.resolve("m.mtl") + ":2: Ni must be a finite number greater than 0, got " + ni
                                           + "; kept the default"), model.warnings());
        }
    }

    @Test
    void objNormalsAndTextureCoordinatesMustFitAFloat() throws IOException {
        String at = dir.resolve("o.obj") + ":4: ";
        assertEquals(at + "normal component '1e300' is beyond the largest float (3.40282e+38)", errorOfObj("vn 0 1e300 0"));
        assertEquals(at + "texture coordinate '-1e40' is beyond the largest float (3.40282e+38)", errorOfObj("vt -1e40 0"));
    }

    @Test
    void valuesInRangeStillLoad() throws Exception {
        Files.writeString(dir.resolve("m.mtl"), "newmtl a\nKd 0 0.5 1\nKs 1 1 1\nNs 1000\nd 0.5\nNi 1.33\nKe 0 0 0\nillum 2\n");
        Path obj = Files.writeString(dir.resolve("m.obj"), "mtllib m.mtl\nusemtl a\n" + TRIANGLE + "vn 0 0 1\nf 1//1 2//1 3//1\n");
        ObjModel model = ObjLoader.load(obj, false);
        assertEquals(1.33, model.materials().get(0).ior());
    }
}
