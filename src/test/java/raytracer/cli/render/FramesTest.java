package raytracer.cli.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.api.FrameFiles;
import raytracer.api.FrameRange;
import raytracer.cli.ErrorReport;
import raytracer.cli.RenderCommandTest;
import raytracer.image.Film;
import raytracer.image.ImageCheck;
import raytracer.image.ImageWriters;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;

/**
 * {@code render SCENE --frames A-B -o pattern}: the frames of one JVM, the scene read once and each
 * frame prepared anew, are the bytes of each frame rendered alone (so nothing one frame's analysis
 * or preparation changed leaks into the next), a frame whose camera is a still's camera is that
 * still's image, {@code --resume} skips only complete files, and misuse is one line.
 */
class FramesTest {
    @TempDir
    Path dir;

    /** A mirror ball by a box under a point and an area light (so samples are drawn, and the analysis has work). */
    private static final String BODY = """
        image: {width: 24, height: 16, samples: 4}
        camera: {eye: [0, 1, 6], look-at: [0, 0.5, 0], fov: 40}
        lights:
          - {type: point, position: [2, 6, 4], intensity: 60}
          - {type: rectangle, corner: [-1, 4, -1], edge-a: [2, 0, 0], edge-b: [0, 0, 2], radiance: 2, samples: 2}
        materials:
          mirror: {type: reflective, kr: 0.6}
        objects:
          - {type: plane, normal: [0, 1, 0]}
          - {type: sphere, name: ball, center: [0, 0.5, 0], radius: 0.5, material: mirror}
          - {type: box, min: [-2, 0, -2], max: [-1.5, 1, -1.5]}
        """;

    private Path scene(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    private Path animated() throws IOException {
        return scene("anim.yaml", BODY + """
            animation:
              frames: 4
              camera: {orbit: {center: [0, 0.5, 0], degrees: 180}}
              objects:
                ball:
                  keys: [{frame: 0, translate: [-1, 0, 0]}, {frame: 4, translate: [1, 0.5, 0]}]
            """);
    }

    @Test
    void framesInOneRunAreTheFramesRenderedAlone() throws IOException {
        Path scene = animated();
        RenderCommandTest.Result all = RenderCommandTest.run(scene.toString(), "--frames", "0-3", "-o", dir.resolve("f-%02d.pfm").toString());
        assertEquals(0, all.code(), all.err());
        assertTrue(all.err().contains("frames 0-3 of " + scene + ": 4 rendered"), all.err());
        for (int f = 0; f < 4; f++) {
            Path alone = dir.resolve("alone-" + f + ".pfm");
            RenderCommandTest.Result one = RenderCommandTest.run(scene.toString(), "--frames", Integer.toString(f), "-o",
                                                                 dir.resolve("alone-%d.pfm").toString(), "-q");
            assertEquals(0, one.code(), one.err());
            assertArrayEquals(Files.readAllBytes(alone), Files.readAllBytes(dir.resolve(String.format("f-%02d.pfm", f))), "frame " + f);
        }
        assertFalse(Arrays.equals(Files.readAllBytes(dir.resolve("f-00.pfm")), Files.readAllBytes(dir.resolve("f-01.pfm"))));
    }

    @Test
    void aFrameWhoseViewIsAStillsIsThatStill() throws IOException {
        Path scene = animated();
        // frame 2 of 4 of a half turn: the eye turned 90 degrees about (0, 0.5, 0), to about (6, 1, 0), as the
        // animation computes it; the ball half way from (-1, 0, 0) to (1, 0.5, 0), which is exact
        Point3D eye = Matrix4.translate(0, 0.5, 0).multiply(Matrix4.rotateY(90)).multiply(Matrix4.translate(0, -0.5, 0))
            .transform(new Point3D(0, 1, 6));
        String still = BODY.replace("eye: [0, 1, 6]", "eye: [" + eye.x() + ", " + eye.y() + ", " + eye.z() + "]")
            .replace("{type: sphere, name: ball, center: [0, 0.5, 0], radius: 0.5, material: mirror}",
                     "{type: sphere, name: ball, center: [0, 0.5, 0], radius: 0.5, material: mirror, transform: [{translate: [0, 0.25, 0]}]}");
        assertEquals(0, RenderCommandTest.run(scene.toString(), "--frames", "2", "-o", dir.resolve("a-%d.pfm").toString(), "-q").code());
        RenderCommandTest.Result r = RenderCommandTest.run(scene("still.yaml", still).toString(), "-o", dir.resolve("still.pfm").toString(), "-q");
        assertEquals(0, r.code(), r.err());
        assertArrayEquals(Files.readAllBytes(dir.resolve("still.pfm")), Files.readAllBytes(dir.resolve("a-2.pfm")));
    }

    /** The frames' folder is made when missing (as the Spark job's file system makes it), so one command serves both. */
    @Test
    void framesFolderIsMadeWhenMissing() throws IOException {
        String pattern = dir.resolve("out").resolve("shots").resolve("f-%04d.png").toString();
        RenderCommandTest.Result r = RenderCommandTest.run(animated().toString(), "--frames", "0-1", "-o", pattern, "-q");
        assertEquals(0, r.code(), r.err());
        assertTrue(Files.isRegularFile(dir.resolve("out/shots/f-0001.png")));
    }

    @Test
    void resumeSkipsCompleteFramesOnly() throws IOException {
        Path scene = animated();
        String pattern = dir.resolve("r-%d.png").toString();
        assertEquals(0, RenderCommandTest.run(scene.toString(), "--frames", "0-1", "-o", pattern, "-q").code());
        FileTime old = FileTime.fromMillis(1_000_000_000_000L);
        Files.setLastModifiedTime(dir.resolve("r-0.png"), old);
        byte[] whole = Files.readAllBytes(dir.resolve("r-1.png"));
        Files.write(dir.resolve("r-1.png"), Arrays.copyOf(whole, whole.length - 5)); // cut short
        RenderCommandTest.Result r = RenderCommandTest.run(scene.toString(), "--frames", "0-3", "-o", pattern, "--resume");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("3 rendered, 1 already complete (--resume)"), r.err());
        assertEquals(old, Files.getLastModifiedTime(dir.resolve("r-0.png")), "a complete frame is not rendered again");
        assertArrayEquals(whole, Files.readAllBytes(dir.resolve("r-1.png")), "a frame cut short is");
        assertNull(ImageCheck.whyNotWhole(dir.resolve("r-3.png"), 24, 16));
        assertTrue(Files.list(dir).noneMatch(p -> p.getFileName().toString().contains("partial")));
    }

    /**
     * A frame is kept only when the whole file is an image of the run's size: a flipped byte (which
     * breaks its chunk's CRC), a stub of the signature and the end chunk, and an image of another
     * size are each rendered again, with a warning naming the file and why.
     */
    @Test
    void resumeRendersDamagedStubAndWrongSizedFramesAgain() throws IOException {
        Path scene = animated();
        String pattern = dir.resolve("d-%d.png").toString();
        assertEquals(0, RenderCommandTest.run(scene.toString(), "--frames", "0-3", "-o", pattern, "-q").code());
        byte[][] whole = new byte[4][];
        for (int f = 0; f < 4; f++) {
            whole[f] = Files.readAllBytes(dir.resolve("d-" + f + ".png"));
        }
        byte[] flipped = whole[1].clone();
        int idat = indexOf(flipped, "IDAT".getBytes(StandardCharsets.US_ASCII));
        flipped[idat + 6] ^= 0x10;
        Files.write(dir.resolve("d-1.png"), flipped);
        byte[] stub = new byte[20];
        System.arraycopy(whole[2], 0, stub, 0, 8);
        System.arraycopy(whole[2], whole[2].length - 12, stub, 8, 12);
        Files.write(dir.resolve("d-2.png"), stub);
        ImageWriters.write(new Film(8, 6), 1, dir.resolve("d-3.png"));
        RenderCommandTest.Result r = RenderCommandTest.run(scene.toString(), "--frames", "0-3", "-o", pattern, "--resume");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains("3 rendered, 1 already complete (--resume)"), r.err());
        assertTrue(r.err().contains("render: warning: " + dir.resolve("d-1.png") + " is damaged (chunk IDAT's CRC does not match); "
                                    + "rendered again"), r.err());
        assertTrue(r.err().contains("render: warning: " + dir.resolve("d-2.png") + " is "), r.err());
        assertTrue(r.err().contains("render: warning: " + dir.resolve("d-3.png") + " is 8x6, not 24x16; rendered again"), r.err());
        for (int f = 1; f < 4; f++) {
            assertArrayEquals(whole[f], Files.readAllBytes(dir.resolve("d-" + f + ".png")), "frame " + f);
        }
    }

    /** The same for PFM frames: a header that is not one, bytes past the pixels, a value that is not finite. */
    @Test
    void resumeChecksAPfmFrameWhole() throws IOException {
        Path scene = animated();
        String pattern = dir.resolve("p-%d.pfm").toString();
        assertEquals(0, RenderCommandTest.run(scene.toString(), "--frames", "0-3", "-o", pattern, "-q").code());
        byte[] good = Files.readAllBytes(dir.resolve("p-1.pfm"));
        byte[] longer = Arrays.copyOf(good, good.length + 12);
        Files.write(dir.resolve("p-1.pfm"), longer);
        byte[] nan = good.clone();
        ByteBuffer.wrap(nan).order(ByteOrder.LITTLE_ENDIAN).putFloat(nan.length - 12 * 5, Float.NaN);
        Files.write(dir.resolve("p-2.pfm"), nan);
        Files.write(dir.resolve("p-3.pfm"), "PF\n24 16\n-1.0\n".getBytes(StandardCharsets.US_ASCII));
        RenderCommandTest.Result r = RenderCommandTest.run(scene.toString(), "--frames", "0-3", "-o", pattern, "--resume", "-q");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().contains(dir.resolve("p-1.pfm") + " is damaged ("), r.err());
        assertTrue(r.err().contains(dir.resolve("p-2.pfm") + " is damaged (pixel "), r.err());
        assertTrue(r.err().contains(dir.resolve("p-3.pfm") + " is cut short"), r.err());
        assertEquals(3, r.lines().length, "a warning a frame, even with --quiet: " + r.err());
        assertArrayEquals(good, Files.readAllBytes(dir.resolve("p-1.pfm")));
    }

    private static int indexOf(byte[] bytes, byte[] part) {
        for (int i = 0; i + part.length <= bytes.length; i++) {
            if (Arrays.equals(bytes, i, i + part.length, part, 0, part.length)) {
                return i;
            }
        }
        throw new AssertionError("not found");
    }

    /** A folder a frame: each frame's folder is made before the first frame renders. */
    @Test
    void aFolderForEachFrameIsMade() throws IOException {
        String pattern = dir.resolve("shot-%d").resolve("frame.png").toString();
        RenderCommandTest.Result r = RenderCommandTest.run(animated().toString(), "--frames", "0-2", "-o", pattern, "-q");
        assertEquals(0, r.code(), r.err());
        for (int f = 0; f < 3; f++) {
            assertTrue(Files.isRegularFile(dir.resolve("shot-" + f).resolve("frame.png")), "frame " + f);
        }
    }

    /** A later frame's output that cannot be written (a folder, an input of the scene) refuses the run before any frame is written. */
    @Test
    void everyFramesOutputIsCheckedBeforeTheFirstRenders() throws IOException {
        Path scene = animated();
        Files.createDirectories(dir.resolve("g-2.png"));
        RenderCommandTest.Result r = RenderCommandTest.run(scene.toString(), "--frames", "0-3", "-o", dir.resolve("g-%d.png").toString());
        assertError(r, "cannot write " + dir.resolve("g-2.png") + ": it is a directory");
        assertFalse(Files.exists(dir.resolve("g-0.png")), "nothing written");
        ImageWriters.write(new Film(2, 2), 1, dir.resolve("t-1.png"));
        byte[] texture = Files.readAllBytes(dir.resolve("t-1.png"));
        Path textured = scene("tex.yaml", Files.readString(scene).replace("materials:", """
            materials:
              wood: {type: matte, texture: {type: image, file: t-1.png}}""")
            .replace("max: [-1.5, 1, -1.5]}", "max: [-1.5, 1, -1.5], material: wood}"));
        r = RenderCommandTest.run(textured.toString(), "--frames", "0-1", "-o", dir.resolve("t-%d.png").toString());
        assertError(r, "cannot write " + dir.resolve("t-1.png") + ": it is one of the scene's inputs");
        assertFalse(Files.exists(dir.resolve("t-0.png")), "nothing written");
        assertArrayEquals(texture, Files.readAllBytes(dir.resolve("t-1.png")));
        Files.writeString(dir.resolve("file"), "a file, not a folder");
        r = RenderCommandTest.run(scene.toString(), "--frames", "0-1", "-o", dir.resolve("file/sub/f-%d.png").toString());
        assertError(r, "cannot write " + dir.resolve("file/sub/f-0.png") + ": ");
        assertTrue(r.err().contains(dir.resolve("file") + " is a regular file, not a folder"), r.err());
    }

    /**
     * A run killed mid-write leaves its temporary file; a frames run removes those of the frames it
     * writes, named as the atomic write names them, and nothing else.
     */
    @Test
    void staleTemporaryFilesOfTheFramesWrittenAreRemoved() throws IOException {
        Path scene = animated();
        String pattern = dir.resolve("s-%d.pfm").toString();
        assertEquals(0, RenderCommandTest.run(scene.toString(), "--frames", "0", "-o", pattern, "-q").code());
        List<String> stale = List.of(".s-1.pfm.3kq9zx1m0a.partial", ".s-2.pfm.0.partial", ".s-3.pfm.3w5e11264sgsf.partial");
        List<String> kept = List.of(".s-0.pfm.abc.partial", ".s-1.pfm.ABC.partial", ".s-1.pfm.abc.partial.bak", "s-1.pfm.abc.partial",
                                    ".s-10.pfm.abc.partial", ".s-1.pfm.local-1-e4f.partial", ".s-1.pfm.3w5e11264sgsfa.partial",
                                    ".s-1.pfm..partial", "other.txt");
        for (String name : stale) {
            Files.writeString(dir.resolve(name), "PF");
        }
        for (String name : kept) {
            Files.writeString(dir.resolve(name), "PF");
        }
        Files.createDirectories(dir.resolve(".s-2.pfm.dir.partial"));
        RenderCommandTest.Result r = RenderCommandTest.run(scene.toString(), "--frames", "0-3", "-o", pattern, "--resume", "-q");
        assertEquals(0, r.code(), r.err());
        for (String name : stale) {
            assertFalse(Files.exists(dir.resolve(name)), name);
        }
        for (String name : kept) {
            assertTrue(Files.exists(dir.resolve(name)), name);
        }
        assertTrue(Files.isDirectory(dir.resolve(".s-2.pfm.dir.partial")), "only files are removed");
    }

    /** Nothing is made, no folder and no file, before the run is accepted: options, scene, and every frame's output. */
    @Test
    void aRefusedRunCreatesNothing() throws IOException {
        Path scene = animated();
        Path folder = dir.resolve("new");
        assertError(RenderCommandTest.run(scene.toString(), "--frames", "2-9", "-o", folder.resolve("deep/f-%d.png").toString()),
                    "--frames 2-9");
        assertFalse(Files.exists(folder), "a range the scene does not have");
        Path broken = scene("broken.yaml", "image: {width: 0}\n");
        RenderCommandTest.Result r = RenderCommandTest.run(broken.toString(), "--frames", "0-1", "-o",
                                                           folder.resolve("f-%d.png").toString());
        assertEquals(1, r.code(), r.err());
        assertFalse(Files.exists(folder), "a scene that does not read");
        // frame 0's folder is missing, frame 1's output is a folder
        Files.createDirectories(dir.resolve("shots/1/f.png"));
        r = RenderCommandTest.run(scene.toString(), "--frames", "0-1", "-o", dir.resolve("shots/%d/f.png").toString());
        assertError(r, "cannot write " + dir.resolve("shots/1/f.png") + ": it is a directory");
        assertFalse(Files.exists(dir.resolve("shots/0")), "a later frame's output that cannot be written");
        r = RenderCommandTest.run(broken.toString(), "-o", folder.resolve("still.png").toString());
        assertEquals(ErrorReport.BAD_USAGE, r.code(), r.err());
        r = RenderCommandTest.run(broken.toString(), "-o", dir.resolve("still.png").toString());
        assertEquals(1, r.code(), r.err());
        assertFalse(Files.exists(folder), "a still's missing folder is an error, not made");
        assertFalse(Files.exists(dir.resolve("still.png")), "a still whose scene does not read");
    }

    @Test
    void patternsAndRanges() {
        assertNull(FrameFiles.whyNotPattern("out/frame-%04d.png"));
        assertNull(FrameFiles.whyNotPattern("100%%-%d.pfm"));
        assertTrue(FrameFiles.whyNotPattern("frame.png").contains("it has 0"));
        assertTrue(FrameFiles.whyNotPattern("%d-%d.png").contains("it has 2"));
        assertTrue(FrameFiles.whyNotPattern("%s.png").contains("a % in it must be"));
        // a zero flag without a width is no conversion String.format can do
        assertTrue(FrameFiles.whyNotPattern("f-%0d.png").contains("a % in it must be"));
        assertNull(FrameFiles.whyNotPattern("f-%5d.png"));
        assertEquals("scene-%04d.png", FrameFiles.defaultPattern(Path.of("dir/scene.yaml")));
        assertEquals(Path.of("f-0012.png"), FrameFiles.name("f-%04d.png", 12));
        assertEquals(new FrameRange(3, 3), FrameRange.parse("3"));
        assertEquals(120, FrameRange.parse("0-119").count());
    }

    @Test
    void misuseIsOneLine() throws IOException {
        Path scene = animated();
        Path still = scene("still.yaml", BODY);
        String out = dir.resolve("x-%d.png").toString();
        assertError(RenderCommandTest.run(scene.toString(), "--frames", "2-9", "-o", out),
                    "--frames 2-9: the scene's animation has 4 frames, 0 to 3");
        assertError(RenderCommandTest.run(still.toString(), "--frames", "0-1", "-o", out), "the scene has no animation section");
        assertError(RenderCommandTest.run(scene.toString(), "--frames", "0-1", "-o", dir.resolve("x.png").toString()),
                    "cannot name the frames: it must hold one %d or %04d");
        assertError(RenderCommandTest.run(scene.toString(), "--frames", "3-1", "-o", out), "the last frame comes before the first");
        assertError(RenderCommandTest.run(scene.toString(), "--resume", "-o", dir.resolve("x.png").toString()), "--resume is for --frames");
        assertError(RenderCommandTest.run(scene.toString(), "--frames", "1", "--repeat", "2", "-o", out), "--repeat is for a still");
    }

    private static void assertError(RenderCommandTest.Result r, String fragment) {
        assertEquals(ErrorReport.BAD_USAGE, r.code(), r.err());
        assertEquals(1, r.lines().length, r.err());
        assertTrue(r.err().startsWith("render: error: ") && r.err().contains(fragment), r.err());
    }
}
