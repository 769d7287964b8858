package raytracer.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.apache.spark.SparkConf;
import org.apache.spark.api.java.JavaSparkContext;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.cli.RenderCommand;
import raytracer.image.Film;
import raytracer.image.ImageWriters;

/**
 * The render on Spark, in local mode with two cores (a task may fail once and be retried), against
 * the command line: a still, as runs of its tiles put together on the driver, and a short
 * animation, a frame per task written by the tasks, are the files render writes, byte for byte,
 * under the box and a Gaussian filter; a task whose first attempt fails (a test's hook, after
 * leaving a temporary file as a killed writer would) is retried, the bytes the same and no
 * temporary file left; a scene error is one line. One Spark context serves every test.
 */
class SparkRenderTest {
    private static JavaSparkContext sc;

    @TempDir
    Path dir;

    @BeforeAll
    static void startSpark() {
        SparkConf conf = new SparkConf().setMaster("local[2,2]").setAppName("SparkRenderTest")
            .set("spark.ui.enabled", "false").set("spark.driver.host", "127.0.0.1");
        sc = new JavaSparkContext(conf);
    }

    @AfterAll
    static void stopSpark() {
        if (sc != null) {
            sc.stop();
        }
    }

    record Result(int code, String err) {
    }

    private static Result spark(String... args) {
        StringWriter err = new StringWriter();
        int code = SparkRender.run(sc, new PrintWriter(err, true), args);
        return new Result(code, err.toString());
    }

    private static void render(String... args) {
        StringWriter err = new StringWriter();
        assertEquals(0, RenderCommand.run(new PrintWriter(err, true), args), err.toString());
    }

    private static String[] with(String[] args, String... more) {
        return Stream.concat(Stream.of(args), Stream.of(more)).toArray(String[]::new);
    }

    @ParameterizedTest(name = "--filter {0}")
    @ValueSource(strings = {"box", "gaussian"})
    void aStillIsTheFileRenderWrites(String filter) throws IOException {
        String[] options = {"scenes/arealight-spheres.yaml", "-W", "70", "-H", "45", "--spp", "4", "--filter", filter,
                            "--filter-stddev", filter.equals("gaussian") ? "1.5" : "0.5", "--no-cache"};
        if (filter.equals("box")) {
            options = new String[] {"scenes/arealight-spheres.yaml", "-W", "70", "-H", "45", "--spp", "4", "--no-cache"};
        }
        render(with(options, "-o", dir.resolve("local.pfm").toString(), "-q"));
        Result r = spark(with(options, "-o", dir.resolve("spark.pfm").toString(), "--tasks", "4"));
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("4 tasks (4 tile runs per frame"), r.err());
        assertArrayEquals(Files.readAllBytes(dir.resolve("local.pfm")), Files.readAllBytes(dir.resolve("spark.pfm")));
        render(with(options, "-o", dir.resolve("local.png").toString(), "-q"));
        assertEquals(0, spark(with(options, "-o", dir.resolve("spark.png").toString(), "-q")).code());
        assertArrayEquals(Files.readAllBytes(dir.resolve("local.png")), Files.readAllBytes(dir.resolve("spark.png")));
    }

    @Test
    void anAnimationIsTheFilesRenderWrites() throws IOException {
        String[] options = {"scenes/turntable-bunny.yaml", "-W", "48", "-H", "36", "--spp", "1", "--frames", "3-6",
                            "--cache-dir", dir.resolve("meshes").toString()};
        render(with(options, "-o", dir.resolve("local-%02d.png").toString(), "-q"));
        Result r = spark(with(options, "-o", dir.resolve("spark-%02d.png").toString()));
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("4 tasks (a task per frame"), r.err());
        assertTrue(r.err().contains("SnakeYAML from"), r.err());
        for (int f = 3; f <= 6; f++) {
            String name = String.format("-%02d.png", f);
            assertTrue(r.err().contains("wrote file:" + dir.resolve("spark" + name)), r.err());
            assertArrayEquals(Files.readAllBytes(dir.resolve("local" + name)), Files.readAllBytes(dir.resolve("spark" + name)), "frame " + f);
        }
        // one frame, fewer than the cores: its tile runs are put together on the driver
        Result one = spark(with(new String[] {"scenes/turntable-bunny.yaml", "-W", "48", "-H", "36", "--spp", "1", "--frames", "5",
                                              "--cache-dir", dir.resolve("meshes").toString()}, "-o", dir.resolve("one-%02d.png").toString()));
        assertEquals(0, one.code(), one.err());
        assertTrue(one.err().contains("tile runs per frame"), one.err());
        assertArrayEquals(Files.readAllBytes(dir.resolve("local-05.png")), Files.readAllBytes(dir.resolve("one-05.png")));
    }

    @Test
    void aTaskThatFailsItsFirstAttemptIsRetriedWithTheSameBytes() throws IOException {
        String[] options = {"scenes/default.yaml", "-W", "64", "-H", "40", "--spp", "1"};
        render(with(options, "-o", dir.resolve("local-0.png").toString(), "-q"));
        sc.setLocalProperty(FrameTask.FAIL_FIRST_ATTEMPT, "1");
        try {
            // the default scene is a still: frame 0 by --tasks 3 runs; then a 3-frame animation, task 1 writing frame 1
            Result still = spark(with(options, "-o", dir.resolve("still.png").toString(), "--tasks", "3"));
            assertEquals(0, still.code(), still.err());
            assertArrayEquals(Files.readAllBytes(dir.resolve("local-0.png")), Files.readAllBytes(dir.resolve("still.png")));
            Path anim = Files.writeString(dir.resolve("spin.yaml"), Files.readString(Path.of("scenes/default.yaml"))
                + "\nanimation: {frames: 3, camera: {orbit: {degrees: 30}}}\n");
            render(anim.toString(), "-W", "64", "-H", "40", "--spp", "1", "--frames", "0-2", "-o", dir.resolve("a-local-%d.png").toString(), "-q");
            Result r = spark(anim.toString(), "-W", "64", "-H", "40", "--spp", "1", "--frames", "0-2", "--tasks", "3", "-o",
                             dir.resolve("a-spark-%d.png").toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(still.err().contains("1 failed attempt retried") && r.err().contains("1 failed attempt retried"),
                       still.err() + r.err());
            for (int f = 0; f < 3; f++) {
                assertArrayEquals(Files.readAllBytes(dir.resolve("a-local-" + f + ".png")), Files.readAllBytes(dir.resolve("a-spark-" + f + ".png")));
            }
        } finally {
            sc.setLocalProperty(FrameTask.FAIL_FIRST_ATTEMPT, null);
        }
        List<String> partial = new ArrayList<>();
        try (Stream<Path> files = Files.list(dir)) {
            files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".partial")).forEach(partial::add);
        }
        assertEquals(List.of(), partial, "temporary files left");
    }

    @Test
    void aSceneErrorIsOneLine() throws IOException {
        Path syntax = Files.writeString(dir.resolve("syntax.yaml"), "objects:\n  - {type: sphere, center: [0, 0, 0]\n");
        assertOneLine(spark(syntax.toString(), "-o", dir.resolve("x.png").toString()), 1, "syntax.yaml:3:1: syntax error");
        // found by the executors, which read the meshes: the driver reads only the image settings
        Path mesh = Files.writeString(dir.resolve("mesh.yaml"), "image: {width: 40, height: 30}\nobjects:\n  - {type: mesh, file: gone.obj}\n");
        assertOneLine(spark(mesh.toString(), "-o", dir.resolve("x.png").toString(), "--no-cache"), 1, "gone.obj");
        assertFalse(Files.exists(dir.resolve("x.png")));
        assertOneLine(spark("scenes/default.yaml", "--frames", "0-3", "-o", dir.resolve("f-%d.png").toString()), 2,
                      "the scene has no animation section");
        assertOneLine(spark("scenes/default.yaml", "-o", dir.resolve("x.jpg").toString()), 2, "unsupported extension");
        assertOneLine(spark("scenes/default.yaml", "--spp", "0"), 2, "--spp must be 1 to");
    }

    /**
     * render's rules for outputs hold for the job: an output that is a texture the scene reads is
     * refused by the task that finds it (the driver reads no more than the image settings) and the
     * texture is left as it was; a folder as the output and a thread count past the limit are
     * refused before any task.
     */
    @Test
    void anOutputIsNeverAnInputAndIsCheckedFirst() throws IOException {
        Path texture = dir.resolve("wood.png");
        Film film = new Film(2, 2);
        film.set(0, 0, 1, 0, 0);
        ImageWriters.write(film, 1, texture);
        byte[] before = Files.readAllBytes(texture);
        Path scene = Files.writeString(dir.resolve("t.yaml"), """
            image: {width: 16, height: 12, samples: 1}
            materials:
              wood: {type: matte, texture: {type: image, file: wood.png}}
            objects:
              - {type: sphere, center: [0, 0, 0], radius: 1, material: wood}
            lights:
              - {type: point, position: [0, 5, 5]}
            """);
        assertOneLine(spark(scene.toString(), "-o", texture.toString(), "--tasks", "2"), 1, "it is one of the scene's inputs");
        assertArrayEquals(before, Files.readAllBytes(texture), "the texture is untouched");
        Files.createDirectory(dir.resolve("folder.png"));
        assertOneLine(spark(scene.toString(), "-o", dir.resolve("folder.png").toString()), 2, "it is a directory");
        assertOneLine(spark(scene.toString(), "--threads", "40000", "-o", dir.resolve("x.png").toString()), 2,
                      "--threads must be 1 to 32767, got 40000");
        assertFalse(Files.exists(dir.resolve("x.png")));
        // the job's own lines (progress, wrote, summary) escape what they echo, as render's do
        Path odd = Files.copy(scene, dir.resolve("t\u001b[31m.yaml"));
        Result r = spark(odd.toString(), "-o", dir.resolve("ok\u001b.png").toString(), "--tasks", "2");
        assertEquals(0, r.code(), r.err());
        assertFalse(r.err().contains("\u001b"), r.err());
        assertTrue(r.err().contains("t\\x1b[31m.yaml"), r.err());
    }

    /**
     * The run failed with {@code code} and one error line holding {@code fragment}, no stack trace.
     * Progress lines may come before it: a job that passes {@link Progress#EVERY_NANOS} prints one,
     * as a slow (or busy) machine's does.
     */
    private static void assertOneLine(Result r, int code, String fragment) {
        assertEquals(code, r.code(), r.err());
        List<String> lines = r.err().strip().lines().filter(l -> !PROGRESS.matcher(l).matches()).toList();
        assertEquals(1, lines.size(), r.err());
        assertTrue(lines.get(0).startsWith("render-spark: error: ") && lines.get(0).contains(fragment), r.err());
        assertFalse(r.err().contains("\tat "), r.err());
    }

    /** A line of {@link Progress#line}. */
    private static final Pattern PROGRESS = Pattern.compile("render-spark: \\d+ of \\d+ .*\\(\\d+%\\), .*");
}
