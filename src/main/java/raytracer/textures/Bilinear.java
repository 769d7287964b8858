package raytracer.textures;

import raytracer.image.Film;
import raytracer.math.MutableRgb;

/**
 * Bilinear interpolation of a film at (s, t) in [0, 1)^2 (t down): s wraps around; t wraps too for
 * repeating textures, or stops at the first and last rows for environment maps (the poles).
 */
final class Bilinear {
    private Bilinear() {
    }

    static void lookup(Film image, double s, double t, MutableRgb out) {
        lookup(image, s, t, true, out);
    }

    static void lookup(Film image, double s, double t, boolean wrapT, MutableRgb out) {
        int w = image.width();
        int h = image.height();
        double x = (s - Math.floor(s)) * w - 0.5;
        double y = (wrapT ? t - Math.floor(t) : Math.max(0, Math.min(1, t))) * h - 0.5;
        int x0 = (int) Math.floor(x);
        int y0 = (int) Math.floor(y);
        double fx = x - x0;
        double fy = y - y0;
        int xa = Math.floorMod(x0, w);
        int xb = Math.floorMod(x0 + 1, w);
        int ya = wrapT ? Math.floorMod(y0, h) : Math.max(0, Math.min(h - 1, y0));
        int yb = wrapT ? Math.floorMod(y0 + 1, h) : Math.max(0, Math.min(h - 1, y0 + 1));
        out.set(mix(image, 0, xa, xb, ya, yb, fx, fy), mix(image, 1, xa, xb, ya, yb, fx, fy),
                mix(image, 2, xa, xb, ya, yb, fx, fy));
    }

    private static double mix(Film f, int c, int xa, int xb, int ya, int yb, double fx, double fy) {
        double top = f.get(xa, ya, c) * (1 - fx) + f.get(xb, ya, c) * fx;
        double bottom = f.get(xa, yb, c) * (1 - fx) + f.get(xb, yb, c) * fx;
        return top * (1 - fy) + bottom * fy;
    }
}
