package raytracer.image;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

/**
 * Loads a texture image into a linear {@link Film}: Radiance .hdr as is, PNG/JPG decoded from sRGB.
 * Every failure names the file and says what is wrong, for scene textures and MTL maps alike.
 */
public final class ImageFiles {
    /** Heap a pixel takes while it is read: up to 4 bytes decoded, then 12 in the film. */
    static final int BYTES_PER_PIXEL = 16;
    private static final String MORE_HEAP = "give Java more heap, e.g. java -Xmx8g -jar render.jar ...";

    private ImageFiles() {
    }

    public static Film read(Path file) throws IOException {
        return read(file, true);
    }

    /**
     * As {@link #read(Path)}; with {@code srgb} false the 8-bit values are taken as they are, for
     * data such as normal maps that are not colours.
     */
    public static Film read(Path file, boolean srgb) throws IOException {
        String notRegular = FileKind.notRegular(file);
        if (notRegular != null) {
            throw new IOException("image " + file + " is " + notRegular);
        }
        if (!Files.isRegularFile(file)) {
            throw new IOException("image " + file + " not found");
        }
        if (file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".hdr")) {
            return RadianceHdr.read(file);
        }
        BufferedImage image = decode(file);
        Film film = new Film(image.getWidth(), image.getHeight());
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int rgb = image.getRGB(x, y);
                double r = (rgb >> 16 & 0xff) / 255.0;
                double g = (rgb >> 8 & 0xff) / 255.0;
                double b = (rgb & 0xff) / 255.0;
                if (srgb) {
                    film.set(x, y, ToneMap.srgbDecode(r), ToneMap.srgbDecode(g), ToneMap.srgbDecode(b));
                } else {
                    film.set(x, y, r, g, b);
                }
            }
        }
        return film;
    }

    /** Reads the size from the header first, so an image too large for the heap is refused before decoding. */
    private static BufferedImage decode(Path file) throws IOException {
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
            if (!readers.hasNext()) {
                throw new IOException("image " + file + " is not a PNG, JPEG or other format ImageIO reads");
            }
            ImageReader reader = readers.next();
            try {
                reader.setInput(in, true, true);
                int width;
                int height;
                try {
                    width = reader.getWidth(0);
                    height = reader.getHeight(0);
                } catch (IOException e) {
                    throw new IOException("cannot read image " + file + ": " + reason(e), e);
                }
                requireHeap(file, width, height, BYTES_PER_PIXEL);
                // a decoder that meets damaged or missing data warns and fills the rest (JPEG: grey);
                // the first warning refuses the image instead, as a damaged PNG is refused
                List<String> warnings = new ArrayList<>();
                reader.addIIOReadWarningListener((source, warning) -> warnings.add(warning));
                BufferedImage image;
                try {
                    image = reader.read(0);
                } catch (IOException e) {
                    throw new IOException("cannot read image " + file + ": " + reason(e), e);
                } catch (OutOfMemoryError e) {
                    throw new IOException("image " + file + " (" + width + " x " + height + " pixels) does not fit in "
                                          + "the heap left; " + MORE_HEAP, e);
                }
                if (!warnings.isEmpty()) {
                    throw new IOException("cannot read image " + file + ": it is damaged or cut short (" + warnings.get(0) + ")");
                }
                return image;
            } finally {
                reader.dispose();
            }
        }
    }

    /**
     * Refuses an image of {@code width x height} that a film cannot hold, or that needs more than
     * the whole heap at {@code bytesPerPixel}: decoding it could only end in OutOfMemoryError.
     */
    static void requireHeap(Path file, int width, int height, int bytesPerPixel) throws IOException {
        if (width < 1 || height < 1 || (long) width * height > Film.MAX_PIXELS) {
            throw new IOException("image " + file + " is " + width + " x " + height + " pixels; an image holds 1 to "
                                  + Film.MAX_PIXELS);
        }
        long need = (long) width * height * bytesPerPixel;
        long max = Runtime.getRuntime().maxMemory();
        if (need > max) {
            throw new IOException("image " + file + " is " + width + " x " + height + " pixels and needs about "
                                  + need / (1024 * 1024) + " MiB to read, more than Java's heap (at most "
                                  + max / (1024 * 1024) + " MiB); " + MORE_HEAP);
        }
    }

    /**
     * What an image reader's exception says, completed by its cause when it says nothing itself
     * (ImageIO's PNG reader wraps whatever it caught as "Caught exception during read: ").
     */
    static String reason(IOException e) {
        String message = e.getMessage() == null ? "" : e.getMessage();
        Throwable cause = e.getCause();
        if (cause == null || !(message.isBlank() || message.endsWith(": "))) {
            return message.isBlank() ? e.getClass().getSimpleName() : message;
        }
        if (cause instanceof OutOfMemoryError) {
            return message + "out of memory (" + cause.getMessage() + "); " + MORE_HEAP;
        }
        return message + (cause.getMessage() != null ? cause.getMessage() : cause.getClass().getSimpleName());
    }
}
