package raytracer.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.channels.SeekableByteChannel;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The files of an animation: {@code -o} as a pattern holding one {@code %d} (or {@code %04d}) for
 * the frame number, and whether a frame's file is complete, for {@code --resume}. The Spark job
 * names its frames alike.
 */
public final class FrameFiles {
    /** One printf integer conversion, with an optional width, zero-padded or not (a zero flag needs a width: %0d throws). */
    private static final Pattern FRAME = Pattern.compile("%(0?[1-9])?d");
    /** The last 12 bytes of every PNG: the IEND chunk, empty, with its CRC. */
    private static final byte[] PNG_END = {0, 0, 0, 0, 'I', 'E', 'N', 'D', (byte) 0xAE, 0x42, 0x60, (byte) 0x82};
    private static final byte[] PNG_START = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

    private FrameFiles() {
    }

    /** The default pattern beside the working directory: {@code <scene name>-%04d.png}. */
    static String defaultPattern(Path scene) {
        String still = OutputFile.defaultFor(scene).toString();
        return still.substring(0, still.length() - ".png".length()).replace("%", "%%") + "-%04d.png";
    }

    /**
     * Why {@code pattern} cannot name the frames, or null: it must hold exactly one {@code %d},
     * {@code %0Nd} or {@code %Nd}, and any other {@code %} doubled.
     */
    public static String whyNotPattern(String pattern) {
        int conversions = 0;
        for (int i = 0; i < pattern.length(); i++) {
            if (pattern.charAt(i) != '%') {
                continue;
            }
            if (pattern.startsWith("%%", i)) {
                i++;
                continue;
            }
            Matcher m = FRAME.matcher(pattern).region(i, pattern.length());
            if (!m.lookingAt()) {
                return "a % in it must be %d, %04d (the frame number) or %% (a percent sign)";
            }
            conversions++;
            i = m.end() - 1;
        }
        return conversions == 1 ? null : "it must hold one %d or %04d for the frame number, e.g. out/frame-%04d.png; it has "
                                         + conversions;
    }

    /** The file of frame {@code frame}. */
    static Path name(String pattern, int frame) {
        return Path.of(format(pattern, frame));
    }

    /** The name of frame {@code frame}: {@code pattern} (checked by {@link #whyNotPattern}) with the number put in. */
    public static String format(String pattern, int frame) {
        return String.format(Locale.ROOT, pattern, frame);
    }

    /**
     * True when {@code file} is a whole image as this program writes them: a PNG from its
     * signature to its IEND chunk, or a PFM whose size its header accounts for. Files are written
     * through a temporary file and a rename, so a file that exists is whole unless something else
     * wrote it; this guards against that too.
     */
    static boolean complete(Path file) {
        if (!Files.isRegularFile(file)) {
            return false;
        }
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        try {
            if (name.endsWith(".png")) {
                return pngComplete(file);
            }
            if (name.endsWith(".pfm")) {
                return pfmComplete(file);
            }
        } catch (IOException e) {
            return false;
        }
        return false;
    }

    private static boolean pngComplete(Path file) throws IOException {
        long size = Files.size(file);
        if (size < PNG_START.length + PNG_END.length) {
            return false;
        }
        try (SeekableByteChannel channel = Files.newByteChannel(file)) {
            ByteBuffer start = ByteBuffer.allocate(PNG_START.length);
            ByteBuffer end = ByteBuffer.allocate(PNG_END.length);
            readFully(channel, start);
            channel.position(size - PNG_END.length);
            readFully(channel, end);
            return Arrays.equals(start.array(), PNG_START) && Arrays.equals(end.array(), PNG_END);
        }
    }

    private static void readFully(SeekableByteChannel channel, ByteBuffer buffer) throws IOException {
        while (buffer.hasRemaining() && channel.read(buffer) >= 0) {
            // read until full or at the end
        }
    }

    /** "PF\nW H\nscale\n" and then 12 bytes per pixel, exactly. */
    private static boolean pfmComplete(Path file) throws IOException {
        byte[] head = new byte[64];
        int n;
        try (InputStream in = Files.newInputStream(file)) {
            n = in.readNBytes(head, 0, head.length);
        }
        String[] lines = new String(head, 0, n, StandardCharsets.US_ASCII).split("\n", 4);
        if (lines.length < 4 || !lines[0].equals("PF")) {
            return false;
        }
        String[] size = lines[1].strip().split("\\s+");
        if (size.length != 2 || !size[0].matches("\\d{1,9}") || !size[1].matches("\\d{1,9}")) {
            return false;
        }
        long header = lines[0].length() + lines[1].length() + lines[2].length() + 3;
        return Files.size(file) == header + 12L * Long.parseLong(size[0]) * Long.parseLong(size[1]);
    }
}
