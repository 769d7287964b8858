package raytracer.cli.show;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Random;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.image.FalseColor;
import raytracer.image.Film;
import raytracer.image.ImageWriters;

/**
 * The {@code --show} window codes pixels as the PNG file does: for every exposure and encoding, its
 * pixels are the file's as an independent PNG reader decodes it; the cost view's live range grows
 * with the tiles, and its final image is the file's false colour.
 */
class ShowToneTest {
    @TempDir
    Path dir;

    private static Film randomFilm(int w, int h, long seed) {
        Random random = new Random(seed);
        Film film = new Film(w, h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                // mostly in [0, 1], some past white and some negative, as a film can hold
                film.set(x, y, 1.3 * random.nextDouble() - 0.05, random.nextDouble() * random.nextDouble(), Math.exp(4 * random.nextGaussian()));
            }
        }
        return film;
    }

    private int[] pngPixels(Film film, double exposure, boolean srgb) throws Exception {
        Path png = dir.resolve("t.png");
        ImageWriters.write(film, exposure, srgb, png);
        BufferedImage image = ImageIO.read(png.toFile());
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xffffff;
        }
        return rgb;
    }

    private static int[] shown(Film film, ShowTone tone) {
        int[] shown = new int[film.width() * film.height()];
        new ShowPixels(film.width(), film.height(), film.width(), film.height(), shown)
            .update(film, 0, 0, film.width(), film.height(), tone);
        return shown;
    }

    @Test
    void theWindowsPixelsAreThePngsForEveryExposureAndEncoding() throws Exception {
        Film film = randomFilm(67, 41, 1);
        for (double exposure : new double[] {1, 0.37, 2.5}) {
            for (boolean srgb : new boolean[] {true, false}) {
                assertArrayEquals(pngPixels(film, exposure, srgb), shown(film, ShowTone.png(exposure, srgb)),
                                  "exposure " + exposure + ", srgb " + srgb);
            }
        }
    }

    @Test
    void theCostViewsRangeGrowsWithTheTilesAndEndsAsTheFile() throws Exception {
        Film cost = new Film(64, 32);
        for (int y = 0; y < 32; y++) {
            for (int x = 0; x < 64; x++) {
                cost.set(x, y, x < 32 ? 10 + x : 100 + y, 0, 0);
            }
        }
        ShowCostTone live = new ShowCostTone();
        assertTrue(live.takeIn(cost, 0, 0, 32, 32), "the first tile sets the range");
        assertFalse(live.takeIn(cost, 0, 0, 32, 32), "the same values again do not change it");
        assertTrue(live.takeIn(cost, 32, 0, 64, 32), "a costlier tile widens it");
        // with every tile taken in, the live range is the image's: the colours are the file's
        double[] range = FalseColor.range(cost);
        Film written = FalseColor.apply(cost, range[0], range[1]);
        int[] file = pngPixels(written, 1, true);
        assertArrayEquals(file, shown(written, ShowTone.png(1, true)));
        assertArrayEquals(file, shown(cost, live));
    }
}
