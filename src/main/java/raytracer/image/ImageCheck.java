package raytracer.image;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Whether a file is a whole image of a given size, PNG or PFM by its extension, as
 * {@link ImageWriters} writes them: every byte read and checked ({@link PngCheck}, {@link PfmCheck}),
 * not only the first and the last, since a file with the right ends can be damaged between them,
 * a stub, or an image of another size. An animation's {@code --resume} keeps only the frames that pass.
 */
public final class ImageCheck {
    private ImageCheck() {
    }

    /**
     * Null when {@code file} is a whole image of {@code width} x {@code height} pixels; else why not,
     * as words that follow the file's name: "is damaged (chunk IDAT's CRC does not match)", "is 64x48,
     * not 320x240", "cannot be read (permission denied)".
     */
    public static String whyNotWhole(Path file, int width, int height) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        boolean png = name.endsWith(".png");
        if (!png && !name.endsWith(".pfm")) {
            return "is not named as a PNG or PFM file";
        }
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            return png ? PngCheck.whyNotWhole(in, width, height) : PfmCheck.whyNotWhole(in, width, height);
        } catch (IOException e) {
            return "cannot be read (" + IoReason.of(e) + ")";
        }
    }
}
