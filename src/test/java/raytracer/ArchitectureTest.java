package raytracer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Keeps the layering of docs/architecture.md honest: dependencies point down the chain math &lt;-
 * core &lt;- families &lt;- image, render, io.obj, io.scene, cache &lt;- api &lt;- cli, families do not
 * use each other (but for the listed exceptions), render sees only core, math and image. A dependency is any name of a
 * class of another package: read from the source with comments and string literals taken out (so
 * an import, a fully qualified name written inline, and a constant the compiler copies into the
 * caller all count), and from the compiled class's constant pool (so a type used without being
 * named, through a method's signature, counts too).
 */
class ArchitectureTest {
    private static final Path SOURCES = Path.of("src/main/java/raytracer");
    /** A package of ours followed by a class name (or an import's '*'). */
    private static final Pattern SOURCE_REFERENCE = Pattern.compile("\\braytracer((?:\\.[a-z][a-z0-9_]*)+)\\.(?:[A-Z]|\\*)");
    /**
     * The same in a class file: a binary name (raytracer/core/World), alone or in a descriptor or
     * signature, where it follows an 'L' (Lraytracer/core/World;).
     */
    private static final Pattern BINARY_REFERENCE =
        Pattern.compile("(?<![A-Za-z0-9_$/])L?raytracer((?:/[a-z][a-z0-9_]*)+)/[A-Z]");

    /** A class of the command line's packages, named in a source. */
    private static final Pattern CLI_CLASS = Pattern.compile("\\braytracer\\.cli(?:\\.[a-z]+)*\\.[A-Z]\\w*");

    private static final Set<String> FAMILIES = Set.of("samplers", "cameras", "shapes", "shapes.mesh", "accel", "brdf",
                                                       "btdf", "textures", "materials", "lights", "tracers", "filters");

    /** For each package, the packages (besides itself) it may use. */
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
        Map.entry("filters", Set.of("math", "core")),
        // a texture needs a decoded raster: the one family allowed to use image (which uses only math)
        Map.entry("textures", Set.of("math", "core", "image")),
        Map.entry("image", Set.of("math")),
        Map.entry("image.chart", Set.of("image")),
        // exact images, computed apart from the renderer's code so that they can check it
        Map.entry("reference", Set.of("math", "image")),
        // files kept between runs: parsed meshes with their trees (the OBJ reader's model in the mesh and
        // BVH layouts) and converge's references (images); writing through a temporary file is image's AtomicFile
        Map.entry("cache", Set.of("math", "image", "shapes", "shapes.mesh", "accel", "io.obj")),
        Map.entry("render", Set.of("math", "core", "image")),
        Map.entry("io.obj", union(FAMILIES, Set.of("math", "core", "image"))),
        // a PLY file is one mesh and nothing else (with the triangle's bound on coordinates)
        Map.entry("io.ply", Set.of("math", "shapes", "shapes.mesh")),
        // a scene's mesh objects are OBJ files: the scene reader uses the OBJ reader, not the reverse
        Map.entry("io.scene", union(FAMILIES, Set.of("math", "core", "image", "io.obj", "io.ply", "reference", "cache"))),
        // a scene file and a render's options made into a scene to render, for the command line and the Spark job
        Map.entry("api", union(FAMILIES, Set.of("math", "core", "image", "render", "io.scene", "cache"))),
        // the command line: the top command and what its programs share (options, errors, terminal, progress) in cli,
        // which dispatches to the programs: render's run, converge, and render's --show window
        Map.entry("cli", union(FAMILIES, Set.of("math", "core", "image", "render", "io.obj", "io.ply", "io.scene", "reference",
                                                 "image.chart", "api", "cache", "cli.render", "cli.converge", "cli.show"))),
        Map.entry("cli.render", union(FAMILIES, Set.of("math", "core", "image", "render", "io.scene", "api", "cli", "cli.show"))),
        // converge warns of dropped samples as render's run report does
        Map.entry("cli.converge", union(FAMILIES, Set.of("math", "core", "image", "image.chart", "render", "io.scene", "reference",
                                                          "api", "cache", "cli", "cli.render"))),
        Map.entry("cli.show", Set.of("image", "render", "cli")));

    private static Set<String> union(Set<String> a, Set<String> b) {
        Set<String> all = new HashSet<>(a);
        all.addAll(b);
        return all;
    }

    @Test
    void dependenciesPointDownTheChain() throws IOException, URISyntaxException {
        List<String> violations = new ArrayList<>();
        Set<String> packages = new TreeSet<>();
        int files = 0;
        try (Stream<Path> paths = Files.walk(SOURCES)) {
            for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))::iterator) {
                files++;
                String pkg = SOURCES.relativize(file.getParent()).toString().replace('/', '.');
                packages.add(pkg);
                for (String used : sourceReferences(Files.readString(file))) {
                    check(pkg, used, SOURCES.relativize(file).toString(), violations);
                }
            }
        }
        Path classes = Path.of(raytracer.core.World.class.getProtectionDomain().getCodeSource().getLocation().toURI())
            .resolve("raytracer");
        int classFiles = 0;
        try (Stream<Path> paths = Files.walk(classes)) {
            for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".class"))::iterator) {
                classFiles++;
                String pkg = classes.relativize(file.getParent()).toString().replace('/', '.');
                for (String used : classReferences(Files.readAllBytes(file))) {
                    check(pkg, used, classes.relativize(file).toString(), violations);
                }
            }
        }
        assertTrue(files > 50, "the sources were not found from " + Path.of("").toAbsolutePath());
        assertTrue(classFiles >= files, "the compiled classes were not found in " + classes);
        Set<String> unruled = new TreeSet<>(packages);
        unruled.removeAll(ALLOWED.keySet());
        assertEquals(Set.of(), unruled, "packages without a rule here");
        assertTrue(violations.isEmpty(), "layering broken:\n" + String.join("\n", new TreeSet<>(violations)));
    }

    private static void check(String pkg, String used, String where, List<String> violations) {
        if (!used.equals(pkg) && !ALLOWED.getOrDefault(pkg, Set.of()).contains(used)) {
            violations.add(where + " uses raytracer." + used);
        }
    }

    /** The packages of ours that a source file names outside its comments and literals. */
    static Set<String> sourceReferences(String source) {
        Set<String> packages = new TreeSet<>();
        Matcher m = SOURCE_REFERENCE.matcher(codeOnly(source));
        while (m.find()) {
            packages.add(m.group(1).substring(1));
        }
        packages.remove(""); // the file's own package line names no class after it
        return packages;
    }

    /**
     * The source with comments, string and character literals and text blocks blanked out
     * (newlines kept), so that only code is left to search.
     */
    static String codeOnly(String source) {
        StringBuilder code = new StringBuilder(source.length());
        int i = 0;
        int n = source.length();
        while (i < n) {
            int end;
            if (source.startsWith("//", i)) {
                end = source.indexOf('\n', i);
                end = end < 0 ? n : end;
            } else if (source.startsWith("/*", i)) {
                end = source.indexOf("*/", i + 2);
                end = end < 0 ? n : end + 2;
            } else if (source.startsWith("\"\"\"", i)) {
                end = closing(source, i + 3, "\"\"\"");
            } else if (source.charAt(i) == '"' || source.charAt(i) == '\'') {
                end = closing(source, i + 1, String.valueOf(source.charAt(i)));
            } else {
                code.append(source.charAt(i++));
                continue;
            }
            for (int k = i; k < end; k++) {
                code.append(source.charAt(k) == '\n' ? '\n' : ' ');
            }
            i = end;
        }
        return code.toString();
    }

    /** The index just past the first unescaped {@code quote} at or after {@code from}. */
    private static int closing(String source, int from, String quote) {
        int i = from;
        while (i < source.length()) {
            if (source.charAt(i) == '\\') {
                i += 2;
            } else if (source.startsWith(quote, i)) {
                return i + quote.length();
            } else {
                i++;
            }
        }
        return source.length();
    }

    /**
     * The packages of ours that a class file refers to: class names, field and method
     * descriptors, generic signatures and annotation types in its constant pool; string
     * constants are text, not references, and are left out.
     */
    static Set<String> classReferences(byte[] classFile) throws IOException {
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(classFile));
        if (in.readInt() != 0xCAFEBABE) {
            throw new IOException("not a class file");
        }
        in.readUnsignedShort(); // minor version
        in.readUnsignedShort(); // major version
        int count = in.readUnsignedShort();
        String[] utf8 = new String[count];
        Set<Integer> stringConstants = new HashSet<>();
        // constant pool tags and sizes: JVM specification (Java SE 17), section 4.4
        for (int i = 1; i < count; i++) {
            int tag = in.readUnsignedByte();
            switch (tag) {
                case 1 -> utf8[i] = in.readUTF();
                case 8 -> stringConstants.add(in.readUnsignedShort());
                case 7, 16, 19, 20 -> in.readUnsignedShort();
                case 15 -> {
                    in.readUnsignedByte();
                    in.readUnsignedShort();
                }
                case 3, 4, 9, 10, 11, 12, 17, 18 -> in.readInt();
                case 5, 6 -> {
                    in.readLong();
                    i++; // a long or double takes two entries
                }
                default -> throw new IOException("unknown constant pool tag " + tag + " at entry " + i);
            }
        }
        Set<String> packages = new TreeSet<>();
        for (int i = 1; i < count; i++) {
            if (utf8[i] != null && !stringConstants.contains(i)) {
                Matcher m = BINARY_REFERENCE.matcher(utf8[i]);
                while (m.find()) {
                    packages.add(m.group(1).substring(1).replace('/', '.'));
                }
            }
        }
        return packages;
    }

    /**
     * The coursework's reference solutions and their registrations (src/solutions/java and
     * src/solutions/registration, never in render.jar) sit in the packages where a student's
     * answers go, so they keep the same layering. The exercises' tests (src/exercises/java) are
     * test code and are not held to it.
     */
    @Test
    void theReferenceSolutionsKeepTheLayeringToo() throws IOException {
        List<String> violations = new ArrayList<>();
        int files = 0;
        for (Path solutions : List.of(Path.of("src/solutions/java/raytracer"), Path.of("src/solutions/registration/raytracer"))) {
            try (Stream<Path> paths = Files.walk(solutions)) {
                for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))::iterator) {
                    files++;
                    String pkg = solutions.relativize(file.getParent()).toString().replace('/', '.');
                    if (!ALLOWED.containsKey(pkg)) {
                        violations.add(solutions.relativize(file) + " is in a package without a rule here");
                    }
                    for (String used : sourceReferences(Files.readString(file))) {
                        check(pkg, used, solutions.getParent().getFileName() + "/" + solutions.relativize(file), violations);
                    }
                }
            }
        }
        assertTrue(files >= 18, "the reference solutions and registrations were not found in src/solutions");
        assertTrue(violations.isEmpty(), "layering broken:\n" + String.join("\n", new TreeSet<>(violations)));
    }

    // ---- the scanners themselves, on planted references ----

    @Test
    void theSourceScanFindsInlineNamesAndSkipsCommentsAndLiterals() {
        String source = """
            package raytracer.render;

            import raytracer.core.World;
            import static raytracer.math.Rounding.gamma;
            import raytracer.image.*;

            /** Not a use: {@link raytracer.accel.FlatBVH}. */
            final class Planted {
                // nor this: raytracer.shapes.Sphere
                /* nor this: raytracer.lights.PointLight */
                String s = "raytracer.textures.Checker \\" raytracer.cameras.Pinhole";
                char c = '"';
                String t = \"""
                    raytracer.samplers.Jittered
                    \""";
                Object m = new raytracer.materials.Dielectric(1.5, null, 0, 1);
                int n = raytracer.io.obj.LineChunks.CHUNK;
            }
            """;
        assertEquals(new TreeSet<>(Set.of("core", "math", "image", "materials", "io.obj")), sourceReferences(source));
    }

    /** Names other packages only inline and in a string; compiled, its constant pool holds both. */
    static final class Planted {
        final Object material = new raytracer.materials.Matte(0.1, 0.9, raytracer.math.RGBColor.WHITE);
        final String text = "raytracer/tracers/Whitted";

        raytracer.brdf.Lambertian brdf() {
            return null;
        }
    }

    @Test
    void theClassScanFindsInlineNamesAndSignaturesAndSkipsStrings() throws IOException {
        byte[] bytes;
        try (InputStream in = Planted.class.getResourceAsStream("ArchitectureTest$Planted.class")) {
            bytes = in.readAllBytes();
        }
        assertEquals(new TreeSet<>(Set.of("materials", "math", "brdf")), classReferences(bytes));
    }

    /**
     * The Spark job (src/spark/java, its own source set and jar) sits above the command line: it
     * renders through the API and takes its options from render's (the only classes of the command
     * line it names); nothing in src/main uses it (the main classes compile without Spark).
     */
    @Test
    void theSparkJobUsesTheApiAndNothingUsesIt() throws IOException {
        Path spark = Path.of("src/spark/java/raytracer/spark");
        Set<String> allowed = Set.of("api", "cli", "render", "image", "io.scene", "core", "math");
        List<String> violations = new ArrayList<>();
        int files = 0;
        try (Stream<Path> paths = Files.walk(spark)) {
            for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))::iterator) {
                files++;
                for (String used : sourceReferences(Files.readString(file))) {
                    if (!used.equals("spark") && !allowed.contains(used)) {
                        violations.add(file + " uses raytracer." + used);
                    }
                }
            }
        }
        try (Stream<Path> paths = Files.walk(SOURCES)) {
            for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))::iterator) {
                if (sourceReferences(Files.readString(file)).contains("spark") || Files.readString(file).contains("import org.apache.spark")) {
                    violations.add(file + " uses the Spark job or Spark");
                }
            }
        }
        assertTrue(files >= 5, "the Spark job's sources were not found in " + spark.toAbsolutePath());
        // of the command line, only what it shares on purpose: render's options and the terminal's escaping
        Set<String> sharedCli = Set.of("raytracer.cli.RenderOptions", "raytracer.cli.ImageOptions", "raytracer.cli.Terminal");
        try (Stream<Path> paths = Files.walk(spark)) {
            for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))::iterator) {
                Matcher named = CLI_CLASS.matcher(codeOnly(Files.readString(file)));
                while (named.find()) {
                    if (!sharedCli.contains(named.group())) {
                        violations.add(file + " uses " + named.group() + ", which the command line does not share");
                    }
                }
            }
        }
        assertTrue(violations.isEmpty(), "layering broken:\n" + String.join("\n", violations));
    }

    /** The chart library stays behind raytracer.image.chart, so it can be swapped in one place. */
    @Test
    void onlyTheChartPackageUsesTheChartLibrary() throws IOException {
        List<String> users = new ArrayList<>();
        try (Stream<Path> paths = Files.walk(SOURCES)) {
            for (Path file : (Iterable<Path>) paths.filter(p -> p.toString().endsWith(".java"))::iterator) {
                if (Files.readString(file).contains("import org.jfree.")
                    && !file.getParent().equals(SOURCES.resolve("image/chart"))) {
                    users.add(SOURCES.relativize(file).toString());
                }
            }
        }
        assertTrue(users.isEmpty(), "JFreeChart used outside raytracer.image.chart: " + users);
    }
}
