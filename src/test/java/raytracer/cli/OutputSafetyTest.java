package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cli.RenderCommandTest.Result;
import raytracer.image.Film;
import raytracer.image.ImageWriters;

/**
 * Nothing the user names is destroyed: an output that is one of the run's inputs
 * is refused, a symbolic link is written through to its target, a FIFO is written into and stays
 * one, and {@code --csv -} is standard output. Every case uses files this test makes; a device is
 * only looked at, never written.
 */
class OutputSafetyTest {
    @TempDir
    Path dir;

    /** Daemon threads: a reader left waiting on a FIFO that was never written must not hold the JVM. */
    private final ExecutorService readers = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "fifo reader");
        t.setDaemon(true);
        return t;
    });

    @AfterEach
    void stopReaders() {
        readers.shutdownNow();
    }

    static final String SCENE = """
        image: {width: 8, height: 6, samples: 1}
        lights:
          - {type: point, position: [0, 5, 5], intensity: 40}
        objects:
          - {type: sphere, center: [0, 0.5, 0], radius: 0.5}
        """;

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    private static Result converge(String... args) {
        return RenderCommandTest.run(Stream.concat(Stream.of("converge"), Stream.of(args)).toArray(String[]::new));
    }

    private Path fifo(String name) throws IOException, InterruptedException {
        Path fifo = dir.resolve(name);
        Process p = new ProcessBuilder("mkfifo", fifo.toString()).redirectErrorStream(true).start();
        assertEquals(0, p.waitFor(), new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8));
        return fifo;
    }

    private Future<byte[]> readAll(Path fifo) {
        return readers.submit(() -> Files.readAllBytes(fifo));
    }

    private static boolean isFifo(Path p) throws IOException {
        return ((Integer) Files.getAttribute(p, "unix:mode", LinkOption.NOFOLLOW_LINKS) & 0170000) == 0010000;
    }

    /** A tiny reference image of the scene's size, as --reference reads it. */
    private Path reference() throws IOException {
        Path ref = dir.resolve("ref.pfm");
        Film film = new Film(8, 6);
        ImageWriters.write(film, 1, ref);
        return ref;
    }

    @Test
    void convergeRefusesACsvThatIsTheSceneTheReferenceOrThePlot() throws IOException {
        Path scene = write("s.yaml", SCENE);
        Path ref = reference();
        byte[] sceneBytes = Files.readAllBytes(scene);
        byte[] refBytes = Files.readAllBytes(ref);
        Path plot = dir.resolve("p.png");
        Result r = converge(scene.toString(), "--spp", "1", "--reference", ref.toString(), "--csv", scene.toString(),
                            "--plot", plot.toString(), "-q");
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("is the scene"), r.err());
        assertArrayEquals(sceneBytes, Files.readAllBytes(scene), "the scene is untouched");
        r = converge(scene.toString(), "--spp", "1", "--reference", ref.toString(), "--csv", ref.toString(), "--plot",
                     plot.toString(), "-q");
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("is the reference"), r.err());
        assertArrayEquals(refBytes, Files.readAllBytes(ref), "the reference is untouched");
        Path table = dir.resolve("t.png");
        r = converge(scene.toString(), "--spp", "1", "--reference", ref.toString(), "--csv", table.toString(), "--plot",
                     table.toString(), "-q");
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("--plot and --csv name the same file"), r.err());
        assertFalse(Files.exists(table));
        // a hard link to the scene is the scene
        Path link = dir.resolve("link.csv");
        Files.createLink(link, scene);
        r = converge(scene.toString(), "--spp", "1", "--reference", ref.toString(), "--csv", link.toString(), "--plot",
                     plot.toString(), "-q");
        assertEquals(2, r.code(), r.err());
        assertArrayEquals(sceneBytes, Files.readAllBytes(scene));
    }

    @Test
    void convergeWritesTheCsvThroughASymlinkAndIntoAFifo() throws Exception {
        Path scene = write("s.yaml", SCENE);
        Path ref = reference();
        Path target = dir.resolve("target.csv");
        Files.writeString(target, "old\n");
        Path link = Files.createSymbolicLink(dir.resolve("link.csv"), target.getFileName());
        Result r = converge(scene.toString(), "--spp", "1", "--reference", ref.toString(), "--csv", link.toString(), "--plot",
                            dir.resolve("p.png").toString(), "-q");
        assertEquals(0, r.code(), r.err());
        assertTrue(Files.isSymbolicLink(link), "the link stays a link");
        assertTrue(Files.readString(target).startsWith("configuration,spp"), Files.readString(target));
        Path fifo = fifo("table.fifo");
        Future<byte[]> read = readAll(fifo);
        r = converge(scene.toString(), "--spp", "1", "--reference", ref.toString(), "--csv", fifo.toString(), "--plot",
                     dir.resolve("p.png").toString(), "-q");
        assertEquals(0, r.code(), r.err());
        assertTrue(isFifo(fifo), "the FIFO stays a FIFO");
        assertTrue(new String(read.get(20, TimeUnit.SECONDS), StandardCharsets.UTF_8).startsWith("configuration,spp"));
    }

    @Test
    void convergeCsvDashIsStandardOutput() throws IOException {
        Path scene = write("s.yaml", SCENE);
        Path ref = reference();
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = RenderCommand.run(new PrintWriter(out, true), new PrintWriter(err, true), "converge", scene.toString(),
                                     "--spp", "1", "--reference", ref.toString(), "--csv", "-", "--plot",
                                     dir.resolve("p.png").toString(), "-q");
        assertEquals(0, code, err.toString());
        assertTrue(out.toString().startsWith("configuration,spp,light_samples"), out.toString());
        assertEquals(2, out.toString().strip().split("\\R").length, "the header and one row, nothing else: " + out);
        assertFalse(Files.exists(Path.of("-")), "no file named '-'");
    }

    @Test
    void renderWritesThroughASymlinkAndIntoAFifo() throws Exception {
        Path scene = write("s.yaml", SCENE);
        Path target = dir.resolve("target.pfm");
        Path link = Files.createSymbolicLink(dir.resolve("link.pfm"), target.getFileName());
        Result r = RenderCommandTest.run(scene.toString(), "-o", link.toString(), "-q");
        assertEquals(0, r.code(), r.err());
        assertTrue(Files.isSymbolicLink(link), "the link stays a link");
        assertEquals(8, ImageWriters.readPfm(target).width(), "the image went to the link's target");
        // a link into a folder that is missing is refused, not replaced
        Path dangling = Files.createSymbolicLink(dir.resolve("dangling.pfm"), dir.resolve("nowhere/x.pfm"));
        r = RenderCommandTest.run(scene.toString(), "-o", dangling.toString(), "-q");
        assertEquals(2, r.code(), r.err());
        assertTrue(Files.isSymbolicLink(dangling));
        Path fifo = fifo("image.pfm");
        Future<byte[]> read = readAll(fifo);
        r = RenderCommandTest.run(scene.toString(), "-o", fifo.toString(), "-q");
        assertEquals(0, r.code(), r.err());
        assertTrue(isFifo(fifo), "the FIFO stays a FIFO");
        byte[] image = read.get(20, TimeUnit.SECONDS);
        assertTrue(new String(image, 0, 3, StandardCharsets.US_ASCII).equals("PF\n"), "a PFM came through the FIFO");
    }

    @Test
    void renderRefusesAnOutputThatIsOneOfItsInputs() throws IOException {
        Path texture = dir.resolve("wood.png");
        Film film = new Film(2, 2);
        film.set(0, 0, 1, 0, 0);
        ImageWriters.write(film, 1, texture);
        byte[] before = Files.readAllBytes(texture);
        Path scene = write("t.yaml", SCENE.replace("objects:", """
            materials:
              wood: {type: matte, texture: {type: image, file: wood.png}}
            objects:""").replace("radius: 0.5}", "radius: 0.5, material: wood}"));
        Result r = RenderCommandTest.run(scene.toString(), "-o", texture.toString(), "-q");
        assertEquals(2, r.code(), r.err());
        assertTrue(r.err().contains("is one of the scene's inputs"), r.err());
        assertArrayEquals(before, Files.readAllBytes(texture), "the texture is untouched");
    }
}
