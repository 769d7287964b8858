package raytracer.filters;

import java.util.List;
import raytracer.core.ParameterException;
import raytracer.core.Parameters;
import raytracer.core.PixelFilter;
import raytracer.core.Registry;

/** Pixel filters by the names scene files and options use: those of the {@link Registry}. */
public final class Filters {
    private Filters() {
    }

    /** The names, in the order they were registered. */
    public static List<String> names() {
        return Registry.standard().filters().names();
    }

    /** The filter of that name with its defaults (the Gaussian with its default width). */
    public static PixelFilter byName(String name) {
        try {
            return Registry.standard().filters().find(name)
                .orElseThrow(() -> new IllegalArgumentException("unknown filter '" + name + "'; allowed: " + String.join(", ", names())))
                .make().make(Parameters.NONE);
        } catch (ParameterException e) {
            // a filter's defaults are its own to get right: one that refuses them is a bug, not a user's mistake
            throw new IllegalStateException("filter '" + name + "' refuses its own defaults: " + e.getMessage(), e);
        }
    }
}
