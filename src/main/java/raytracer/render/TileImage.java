package raytracer.render;

import java.util.List;
import raytracer.core.PixelFilter;
import raytracer.image.Film;

/**
 * The image made from tiles rendered apart, perhaps on other machines ({@link Renderer#renderTiles}):
 * the box filter's pixels copied into the film; a wider filter's sums added up pixel by pixel in
 * the order of the tile list and divided by their weight, as a render of the whole image does
 * ({@link FilteredImage#resolve}), so the film is the same to the bit for every filter.
 */
public final class TileImage {
    private TileImage() {
    }

    /**
     * Fills {@code film} from {@code tiles}: every tile of the film's list exactly once, each as
     * the list places it, rendered under {@code filter}; IllegalArgumentException otherwise.
     */
    public static void assemble(List<TilePixels> tiles, PixelFilter filter, Film film) {
        List<int[]> list = TileOrder.tiles(film.width(), film.height());
        TilePixels[] byIndex = new TilePixels[list.size()];
        for (TilePixels t : tiles) {
            if (t.index() < 0 || t.index() >= list.size()) {
                throw new IllegalArgumentException("tile " + t.index() + " is not one of the " + list.size() + " tiles of a "
                                                   + film.width() + "x" + film.height() + " image");
            }
            int[] place = list.get(t.index());
            if (place[0] != t.x0() || place[1] != t.y0() || place[2] != t.x1() || place[3] != t.y1()) {
                throw new IllegalArgumentException("tile " + t.index() + " covers " + t.x0() + ", " + t.y0() + " to " + t.x1() + ", "
                                                   + t.y1() + ", not the list's " + place[0] + ", " + place[1] + " to " + place[2]
                                                   + ", " + place[3]);
            }
            if (t.isBox() != filter.isBox()) {
                throw new IllegalArgumentException("tile " + t.index() + " was rendered under another filter than " + filter.name());
            }
            if (byIndex[t.index()] != null) {
                throw new IllegalArgumentException("tile " + t.index() + " is given twice");
            }
            byIndex[t.index()] = t;
        }
        for (int i = 0; i < byIndex.length; i++) {
            if (byIndex[i] == null) {
                throw new IllegalArgumentException("tile " + i + " of " + byIndex.length + " is missing");
            }
        }
        if (filter.isBox()) {
            for (TilePixels t : byIndex) {
                float[] rgb = t.rgb();
                for (int y = t.y0(), i = 0; y < t.y1(); y++) {
                    for (int x = t.x0(); x < t.x1(); x++, i += 3) {
                        film.set(x, y, rgb[i], rgb[i + 1], rgb[i + 2]);
                    }
                }
            }
            return;
        }
        FilteredImage.check(filter);
        FilteredTile[] filtered = new FilteredTile[byIndex.length];
        for (int i = 0; i < byIndex.length; i++) {
            TilePixels t = byIndex[i];
            filtered[i] = new FilteredTile(filter, t.x0(), t.y0(), t.x1(), t.y1(), t.sums());
        }
        FilteredImage.resolve(filtered, film, filter.reach());
    }
}
