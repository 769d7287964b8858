package raytracer.cli.show;

import raytracer.image.DisplayCodes;
import raytracer.image.Film;

/** How the {@code --show} window turns a film pixel into the 0xRRGGBB it shows. */
interface ShowTone {
    int rgb(Film film, int x, int y);

    /**
     * Takes in the finished pixels x0 .. x1 - 1, y0 .. y1 - 1 and says whether the tone changed, so
     * that every pixel shown so far must be made again; a fixed tone never changes.
     */
    default boolean takeIn(Film film, int x0, int y0, int x1, int y1) {
        return false;
    }

    /** The PNG's codes: the same {@link DisplayCodes} as {@code ImageWriters} uses, so the same bytes. */
    static ShowTone png(double exposure, boolean srgb) {
        DisplayCodes codes = new DisplayCodes(exposure, srgb);
        return (film, x, y) -> codes.code(film.get(x, y, 0)) << 16 | codes.code(film.get(x, y, 1)) << 8 | codes.code(film.get(x, y, 2));
    }
}
