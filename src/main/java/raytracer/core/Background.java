package raytracer.core;

import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/** What a ray that hits nothing sees: a constant colour or an environment map. */
@FunctionalInterface
public interface Background {

    /** Writes the radiance arriving from infinitely far along {@code ray} into {@code out}. */
    void radiance(Ray ray, MutableRgb out);
}
