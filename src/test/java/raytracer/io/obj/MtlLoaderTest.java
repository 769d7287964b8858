package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Material libraries as exporters write them: texture options anywhere, Windows paths, odd keys. */
class MtlLoaderTest {
    @TempDir
    Path dir;

    private final List<String> warnings = new ArrayList<>();

    private Map<String, ObjMaterial> load(String text) throws IOException, ObjException {
        Path file = dir.resolve("lib.mtl");
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return MtlLoader.load(file, warnings);
    }

    private Path texture(String name) throws IOException {
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        Files.write(file, new byte[] {1});
        return file;
    }

    @Test
    void everyTextureOptionIsSkippedWithItsArguments() throws Exception {
        Path png = texture("texture.png");
        String[] options = {"-blendu on", "-blendv off", "-boost 2.5", "-cc on", "-clamp off", "-imfchan r", "-mm 0 1",
                            "-o 0.1", "-o 0.1 0.2", "-o 0.1 0.2 0.3", "-s 2 2 1", "-t 0.1 0.1", "-texres 512",
                            "-type sphere", "-colorspace sRGB", "-bm 0.3"};
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < options.length; i++) {
            // before the name, after it, and on both sides
            text.append("newmtl before").append(i).append("\nmap_Kd ").append(options[i]).append(" texture.png\n");
            text.append("newmtl after").append(i).append("\nmap_Kd texture.png ").append(options[i]).append('\n');
            text.append("newmtl both").append(i).append("\nmap_Kd ").append(options[i]).append(" texture.png ")
                .append(options[(i + 1) % options.length]).append('\n');
        }
        Map<String, ObjMaterial> m = load(text.toString());
        assertEquals(3 * options.length, m.size());
        for (ObjMaterial material : m.values()) {
            assertEquals(png, material.mapKd(), material.name());
        }
        assertTrue(warnings.isEmpty(), warnings.toString());
    }

    @Test
    void theFileNameIsWhatRemainsSpacesIncluded() throws Exception {
        Path spaced = texture("my textures/wood grain.png");
        Path bump = texture("bump.jpg");
        Map<String, ObjMaterial> m = load("newmtl a\nmap_Kd -s 1 1 1 my textures/wood grain.png -blendu on\n"
                                          + "newmtl b\nmap_Bump bump.jpg -bm 1.5\n"
                                          + "newmtl c\nbump -bm 0.25 -clamp on bump.jpg\n");
        assertEquals(spaced, m.get("a").mapKd());
        assertEquals(bump, m.get("b").mapBump());
        assertEquals(1.5, m.get("b").bumpScale(), 0, "-bm after the name is read too");
        assertEquals(0.25, m.get("c").bumpScale(), 0);
        assertTrue(warnings.isEmpty(), warnings.toString());
    }

    @Test
    void backslashesSeparateFolders() throws Exception {
        Path png = texture("maps/texture.png");
        Map<String, ObjMaterial> m = load("newmtl a\nmap_Kd .\\maps\\texture.png\nnewmtl b\nmap_Kd maps\\texture.png\n");
        assertEquals(png, m.get("a").mapKd());
        assertEquals(png, m.get("b").mapKd());
        assertTrue(warnings.isEmpty(), warnings.toString());
    }

    @Test
    void missingTexturesAndBadValuesAreWarnings() throws Exception {
        Map<String, ObjMaterial> m = load("newmtl a\nKd 1 x 0\nmap_Kd -o 1 nowhere.png\nfoo 1\nfoo 2\nNs lots\n");
        assertNull(m.get("a").mapKd());
        assertEquals(List.of(dir.resolve("lib.mtl") + ":2: expected a colour 'r g b', got '1 x 0'; kept the default",
                             dir.resolve("lib.mtl") + ":3: texture " + dir.resolve("nowhere.png") + " is missing; the material is used without it",
                             dir.resolve("lib.mtl") + ":4: unknown keyword 'foo' ignored (2 lines)",
                             dir.resolve("lib.mtl") + ":6: expected a number, got 'lots'; kept the default"), warnings);
    }

    @Test
    void aByteOrderMarkDoesNotHideTheFirstMaterial() throws Exception {
        Path file = dir.resolve("bom.mtl");
        Files.write(file, new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF, 'n', 'e', 'w', 'm', 't', 'l', ' ', 'a', '\n'});
        assertEquals(List.of("a"), List.copyOf(MtlLoader.load(file, warnings).keySet()));
        assertTrue(warnings.isEmpty(), warnings.toString());
    }
}
