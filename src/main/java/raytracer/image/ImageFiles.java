package raytracer.image;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;

/** Loads a texture image into a linear {@link Film}: Radiance .hdr as is, PNG/JPG decoded from sRGB. */
public final class ImageFiles {
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
        if (!Files.isRegularFile(file)) {
            throw new IOException("image " + file + " not found");
        }
        if (file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".hdr")) {
            return RadianceHdr.read(file);
        }
        BufferedImage image = ImageIO.read(file.toFile());
        if (image == null) {
            throw new IOException("image " + file + " is not a PNG, JPEG or other format ImageIO reads");
        }
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
}
