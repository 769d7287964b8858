package raytracer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cli.RenderCommand;

/**
 * The exercises of docs/teaching.md can be done as written. For each exercise of
 * src/solutions/exercises.tsv its test, its reference solution, its registration (a class the
 * student adds, kept in src/solutions/registration) and its example scene exist; the example scene
 * fails to load before the registration, naming what is missing; in a copy of today's
 * src/main/java with the nine solutions and registration classes added, and the registrations'
 * names added to a copy of the services file (the one file of src/main a student edits), the code
 * compiles under the build's warnings-as-errors; rendered by that copy's command line, every example
 * scene comes out the same to the bit with and without the scene analysis. tools/exercise-walk goes
 * further: it runs each exercise's test and, with all nine registered, the whole suite.
 *
 * <p>In a student's tree, where some exercises are done (their classes are in src/main), the
 * examples of those exercises load, and the reference registrations are not applied over the
 * student's own: those checks are for the tree as shipped, and are skipped with a reason.
 */
class ExerciseRegistrationTest {
    private static final Path EXERCISES = Path.of("src/solutions/exercises.tsv");
    /** The list of registrations, which java.util.ServiceLoader reads from the class path. */
    private static final String SERVICES = "META-INF/services/raytracer.core.Registration";

    /** One line of the manifest. */
    record Exercise(int number, String test, List<String> files, String registration, String scene, List<String> options) {
        Path scenePath() {
            return Path.of("src/exercises/scenes", scene);
        }

        /** The registration class's source, relative to a source folder. */
        String registrationFile() {
            return registration.replace('.', '/') + ".java";
        }

        /** True when the exercise's classes are in src/main: a student has done it. */
        boolean done() {
            return files.stream().anyMatch(f -> Files.exists(Path.of("src/main/java", f)));
        }
    }

    static List<Exercise> exercises() throws IOException {
        List<Exercise> list = new ArrayList<>();
        for (String line : Files.readAllLines(EXERCISES)) {
            if (line.isBlank() || line.startsWith("#")) {
                continue;
            }
            String[] c = line.split("\t");
            assertEquals(6, c.length, EXERCISES + ": six tab-separated columns in '" + line + "'");
            list.add(new Exercise(Integer.parseInt(c[0]), c[1], List.of(c[2].split(",")), c[3], c[4],
                                  c[5].equals("-") ? List.of() : List.of(c[5].split(" "))));
        }
        return list;
    }

    @Test
    void everyExerciseHasItsTestSolutionRegistrationAndScene() throws IOException {
        List<Exercise> exercises = exercises();
        assertEquals(List.of(1, 2, 3, 4, 5, 6, 7, 8, 9), exercises.stream().map(Exercise::number).toList(),
                     "the nine exercises of docs/teaching.md, in order");
        for (Exercise e : exercises) {
            assertTrue(Files.isRegularFile(Path.of("src/exercises/java/raytracer/exercises", e.test() + ".java")),
                       "exercise " + e.number() + ": its test " + e.test());
            for (String f : e.files()) {
                assertTrue(Files.isRegularFile(Path.of("src/solutions/java", f)), "exercise " + e.number() + ": its solution " + f);
            }
            assertTrue(Files.isRegularFile(Path.of("src/solutions/registration", e.registrationFile())),
                       "exercise " + e.number() + ": its registration " + e.registrationFile());
            assertTrue(Files.isRegularFile(e.scenePath()), "exercise " + e.number() + ": its example scene " + e.scenePath());
        }
    }

    @Test
    void eachExampleSceneNeedsItsRegistration(@TempDir Path dir) throws IOException {
        for (Exercise e : exercises()) {
            if (e.done()) {
                continue; // a student's class and registration are in place: the example loads
            }
            StringWriter err = new StringWriter();
            List<String> args = new ArrayList<>(List.of(e.scenePath().toString(), "-W", "8", "-H", "6", "--spp", "1", "-q",
                                                        "--no-cache", "-o", dir.resolve(e.number() + ".pfm").toString()));
            args.addAll(e.options());
            int code = RenderCommand.run(new PrintWriter(err, true), args.toArray(String[]::new));
            assertNotEquals(0, code, "exercise " + e.number() + ": " + e.scene() + " renders before its registration: "
                                     + "it does not show the exercise's scene keys");
            assertTrue(err.toString().contains("unknown"), "exercise " + e.number() + ": the error names what is unknown: " + err);
        }
    }

    @Test
    void theRegistrationsCompileAndRenderTheExampleScenes(@TempDir Path dir) throws Exception {
        List<Exercise> exercises = exercises();
        List<Integer> done = exercises.stream().filter(Exercise::done).map(Exercise::number).toList();
        assumeTrue(done.isEmpty(), "exercises " + done + " are done in src/main: the reference registrations are checked "
                                   + "on the tree as shipped, not over a student's own");
        Path main = dir.resolve("src/main/java");
        copyTree(Path.of("src/main/java"), main);
        Path resources = dir.resolve("resources");
        copyTree(Path.of("src/main/resources"), resources);
        // as a student does: the classes added beside src/main's, and one line each in the list of registrations
        StringBuilder lines = new StringBuilder();
        for (Exercise e : exercises) {
            for (String f : e.files()) {
                Files.copy(Path.of("src/solutions/java", f), main.resolve(f));
            }
            Files.copy(Path.of("src/solutions/registration", e.registrationFile()), main.resolve(e.registrationFile()));
            lines.append(e.registration()).append('\n');
        }
        Files.writeString(resources.resolve(SERVICES), lines, StandardCharsets.UTF_8, java.nio.file.StandardOpenOption.APPEND);

        Path classes = dir.resolve("classes");
        compile(main, classes);
        URL[] urls = Stream.concat(Stream.of(classes, resources), dependencies().stream()).map(ExerciseRegistrationTest::url)
            .toArray(URL[]::new);
        try (URLClassLoader loader = new URLClassLoader(urls, ClassLoader.getPlatformClassLoader())) {
            Method run = loader.loadClass("raytracer.cli.RenderCommand").getMethod("run", PrintWriter.class, String[].class);
            for (Exercise e : exercises) {
                byte[][] images = new byte[2][];
                for (int analysis = 0; analysis < 2; analysis++) {
                    Path out = dir.resolve(e.number() + "-" + analysis + ".pfm");
                    List<String> args = new ArrayList<>(List.of(e.scenePath().toString(), "-W", "24", "-H", "16", "--spp", "2", "-q",
                                                                "--no-cache", "-o", out.toString()));
                    args.addAll(e.options());
                    if (analysis == 1) {
                        args.add("--no-skip");
                    }
                    StringWriter err = new StringWriter();
                    int code = (Integer) run.invoke(null, new PrintWriter(err, true), args.toArray(String[]::new));
                    assertEquals(0, code, "exercise " + e.number() + ", registered: " + String.join(" ", args) + ": " + err);
                    images[analysis] = Files.readAllBytes(out);
                }
                assertArrayEquals(images[0], images[1], "exercise " + e.number() + ": " + e.scene()
                                                        + " differs with --no-skip: the scene analysis left out work the solution needs");
            }
        }
    }

    /** Compiles every source under {@code sources} into {@code classes} as build.gradle compiles src/main. */
    private static void compile(Path sources, Path classes) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertTrue(javac != null, "a JDK's compiler is needed (this test runs on a JRE)");
        List<String> args = new ArrayList<>(List.of("--release", "17", "-Xlint:all,-processing,-serial", "-Werror", "-proc:none",
                                                    "-encoding", "UTF-8", "-d", classes.toString(), "-cp",
                                                    String.join(File.pathSeparator, dependencies().stream().map(Path::toString).toList())));
        try (Stream<Path> files = Files.walk(sources)) {
            files.filter(f -> f.toString().endsWith(".java")).forEach(f -> args.add(f.toString()));
        }
        if (javac.run(null, null, null, args.toArray(String[]::new)) != 0) {
            fail("src/main/java with the nine solutions registered does not compile (javac's messages above)");
        }
    }

    /** The libraries on this test's class path (picocli, SnakeYAML, JFreeChart, ...): its jar files. */
    private static List<Path> dependencies() {
        return Arrays.stream(System.getProperty("java.class.path").split(File.pathSeparator))
            .filter(p -> p.endsWith(".jar"))
            .map(Path::of)
            .toList();
    }

    private static URL url(Path path) {
        try {
            return path.toUri().toURL();
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }

    private static void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> files = Files.walk(from)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Path target = to.resolve(from.relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(f, target);
                }
            }
        }
    }
}
