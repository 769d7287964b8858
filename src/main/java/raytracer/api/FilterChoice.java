package raytracer.api;

import raytracer.core.PixelFilter;
import raytracer.filters.Filters;
import raytracer.filters.Gaussian;

/**
 * What {@code --filter} and {@code --filter-stddev} ask of the scene's pixel filter. A null name
 * and width leave the scene's; a width alone asks for the Gaussian of that width; a filter named
 * without a width is the scene's own, width and all, when the scene has that filter, else the
 * named filter at its default width.
 */
public record FilterChoice(String name, Double stddev) implements java.io.Serializable {

    /** The choice, or IllegalArgumentException saying what is wrong with it. */
    public static FilterChoice parse(String name, Double stddev) {
        if (name != null && !Filters.names().contains(name)) {
            throw new IllegalArgumentException("unknown --filter '" + name + "'; allowed: " + String.join(", ", Filters.names()));
        }
        if (stddev != null && name != null && !name.equals("gaussian")) {
            throw new IllegalArgumentException("--filter-stddev is for --filter gaussian, not " + name);
        }
        if (stddev != null && !Gaussian.allows(stddev)) {
            throw new IllegalArgumentException("--filter-stddev must be " + Gaussian.MIN_STDDEV + " to " + Gaussian.MAX_STDDEV
                                               + " pixels, got " + stddev);
        }
        return new FilterChoice(name, stddev);
    }

    /** The filter to render with, given the scene's. */
    public PixelFilter applyTo(PixelFilter scene) {
        if (name == null && stddev == null) {
            return scene;
        }
        if (stddev != null) {
            return new Gaussian(stddev);
        }
        // a width alone is the Gaussian's; the scene's own filter, named again, keeps its width
        return scene.name().equals(name) ? scene : Filters.byName(name);
    }
}
