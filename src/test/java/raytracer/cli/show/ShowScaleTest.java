package raytracer.cli.show;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The {@code --show} window's fit to the screen: the largest size of the image's shape that fits,
 * each shown pixel the rounded mean of the whole image pixels it spans, and a reduction made tile by
 * tile in any order the same as one of the whole image.
 */
class ShowScaleTest {
    @Test
    void anImageThatFitsIsShownAsItIs() {
        assertArrayEquals(new int[] {640, 480}, ShowScale.fit(640, 480, 640, 480));
        assertArrayEquals(new int[] {16, 8}, ShowScale.fit(16, 8, 1920, 1050));
    }

    @Test
    void aLargerImageShrinksToFitKeepingItsShape() {
        assertArrayEquals(new int[] {960, 540}, ShowScale.fit(3840, 2160, 1920, 540));
        assertArrayEquals(new int[] {200, 150}, ShowScale.fit(320, 240, 200, 150));
        Random random = new Random(27);
        for (int i = 0; i < 10_000; i++) {
            int w = 1 + random.nextInt(20_000);
            int h = 1 + random.nextInt(20_000);
            int mw = 1 + random.nextInt(3000);
            int mh = 1 + random.nextInt(3000);
            int[] s = ShowScale.fit(w, h, mw, mh);
            String c = w + "x" + h + " in " + mw + "x" + mh + ": " + s[0] + "x" + s[1];
            assertTrue(s[0] >= 1 && s[1] >= 1 && s[0] <= Math.max(1, Math.min(w, mw)) && s[1] <= Math.max(1, Math.min(h, mh)), c);
            if ((w > mw || h > mh) && s[0] > 1 && s[1] > 1) {
                // one side fills its bound, up to the rounding down (a side held at one pixel cannot keep the shape)
                assertTrue(s[0] >= mw - 1 || s[1] >= mh - 1, c);
                double aspect = (double) w / h;
                assertEquals(aspect, (double) s[0] / s[1], aspect * (1.0 / s[1] + 1.0 / s[0]) * 1.01 + 1e-12, c);
            }
        }
    }

    @Test
    void halvingAveragesEachTwoByTwoBlock() {
        int[] image = {
            0x000000, 0x020406, 0xff0000, 0xff0000,
            0x010101, 0x010101, 0x00ff00, 0x0000ff,
        };
        int[] shown = new int[2];
        assertArrayEquals(new int[] {0, 0, 2, 1}, ShowScale.reduce(image, 4, 2, shown, 2, 1, 0, 0, 4, 2));
        // (0 + 2 + 1 + 1) / 4 = 1, (0 + 4 + 1 + 1) / 4 = 1.5 rounds up, (0 + 6 + 1 + 1) / 4 = 2
        assertEquals(0x010202, shown[0]);
        // (255 + 255 + 0 + 0) / 4 = 127.5 up, (0 + 0 + 255 + 0) / 4 = 63.75, (0 + 0 + 0 + 255) / 4
        assertEquals(0x804040, shown[1]);
    }

    @Test
    void theSpansOfShownPixelsCoverTheImageOnce() {
        for (int image = 1; image < 300; image++) {
            for (int shown = 1; shown <= image; shown++) {
                assertEquals(0, ShowScale.start(0, image, shown));
                assertEquals(image, ShowScale.start(shown, image, shown));
                for (int i = 0; i < shown; i++) {
                    assertTrue(ShowScale.start(i + 1, image, shown) > ShowScale.start(i, image, shown), image + " in " + shown);
                }
            }
        }
    }

    @Test
    void aUniformImageStaysUniformAtAnyScale() {
        int[] image = new int[97 * 61];
        java.util.Arrays.fill(image, 0x3c7fe1);
        for (int[] size : new int[][] {{96, 60}, {50, 31}, {7, 3}, {1, 1}, {97, 1}}) {
            int[] shown = new int[size[0] * size[1]];
            ShowScale.reduce(image, 97, 61, shown, size[0], size[1], 0, 0, 97, 61);
            for (int rgb : shown) {
                assertEquals(0x3c7fe1, rgb, size[0] + "x" + size[1]);
            }
        }
    }

    @Test
    void tileByTileInAnyOrderIsTheWholeImagesReduction() {
        Random random = new Random(2);
        int w = 157;
        int h = 93;
        int[] image = new int[w * h];
        for (int i = 0; i < image.length; i++) {
            image[i] = random.nextInt(0x1000000);
        }
        for (int[] size : new int[][] {{100, 59}, {51, 30}, {156, 92}, {13, 8}}) {
            int[] whole = new int[size[0] * size[1]];
            ShowScale.reduce(image, w, h, whole, size[0], size[1], 0, 0, w, h);
            // tiles of 32 in a shuffled order, each reduced once its pixels are in the image
            int[] growing = new int[w * h];
            int[] shown = new int[whole.length];
            java.util.List<int[]> tiles = new java.util.ArrayList<>();
            for (int y = 0; y < h; y += 32) {
                for (int x = 0; x < w; x += 32) {
                    tiles.add(new int[] {x, y, Math.min(w, x + 32), Math.min(h, y + 32)});
                }
            }
            java.util.Collections.shuffle(tiles, random);
            for (int[] t : tiles) {
                for (int y = t[1]; y < t[3]; y++) {
                    System.arraycopy(image, y * w + t[0], growing, y * w + t[0], t[2] - t[0]);
                }
                int[] changed = ShowScale.reduce(growing, w, h, shown, size[0], size[1], t[0], t[1], t[2], t[3]);
                assertTrue(changed[0] >= 0 && changed[1] >= 0 && changed[0] + changed[2] <= size[0] && changed[1] + changed[3] <= size[1]);
            }
            assertArrayEquals(whole, shown, size[0] + "x" + size[1]);
        }
    }
}
