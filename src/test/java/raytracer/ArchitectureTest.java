package raytracer;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Keeps the layering of STYLE.md honest by reading imports: dependencies point down the chain
 * math <- core <- families <- image, render, io <- cli, families do not use each other (but for
 * the listed exceptions), and render sees only core.
 */
class ArchitectureTest {
    private static final Path SOURCES = Path.of("src/main/java/raytracer");
    private static final Pattern IMPORT = Pattern.compile("^import (?:static )?raytracer\\.([a-z.]+)\\.[A-Z]", Pattern.MULTILINE);

    /** For each package, the packages (besides itself) it may import from. */
    private static final Map<String, Set<String>> ALLOWED = Map.ofEntries(
        Map.entry("math", Set.of()),
        Map.entry("core", Set.of("math")),
        Map.entry("samplers", Set.of("math", "core")),
        Map.entry("cameras", Set.of("math", "core")),
        Map.entry("shapes", Set.of("math", "core")),
        // a mesh's triangles take the watertight test of the single triangle
        Map.entry("shapes.mesh", Set.of("math", "core", "shapes")),
        Map.entry("accel", Set.of("math", "core", "shapes", "shapes.mesh")),
        Map.entry("brdf", Set.of("math", "core")),
        Map.entry("btdf", Set.of("math", "core")),
        Map.entry("materials", Set.of("math", "core", "brdf", "btdf")),
        Map.entry("lights", Set.of("math", "core")),
        Map.entry("tracers", Set.of("math", "core")),
        // a texture needs a decoded raster: the one family allowed to use image (which uses only math)
        Map.entry("textures", Set.of("math", "core", "image")),
        Map.entry("image", Set.of("math")),
        Map.entry("render", Set.of("math", "core", "image")));

    @Test
    void importsPointDownTheChain() throws IOException {
        List<String> violations = new ArrayList<>();
        int files = 0;
        try (Stream<Path> paths = Files.walk(SOURCES)) {
            for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))::iterator) {
                files++;
                String pkg = SOURCES.relativize(file.getParent()).toString().replace('/', '.');
                Set<String> allowed = ALLOWED.get(pkg);
                if (allowed == null) {
                    continue; // io.*, scenes and cli may use every family
                }
                Matcher m = IMPORT.matcher(Files.readString(file));
                while (m.find()) {
                    String target = m.group(1);
                    if (!target.equals(pkg) && !allowed.contains(target)) {
                        violations.add(SOURCES.relativize(file) + " imports raytracer." + target);
                    }
                }
            }
        }
        assertTrue(files > 50, "the sources were not found from " + Path.of("").toAbsolutePath());
        assertTrue(violations.isEmpty(), "layering broken:\n" + String.join("\n", violations));
    }
}
