package raytracer.filters;

import java.util.List;
import raytracer.core.PixelFilter;

/** Pixel filters by the names scene files and options use. */
public final class Filters {
    private static final List<String> NAMES = List.of("box", "gaussian");

    private Filters() {
    }

    public static List<String> names() {
        return NAMES;
    }

    /** The filter of that name; the Gaussian with its default width. */
    public static PixelFilter byName(String name) {
        return switch (name) {
            case "box" -> PixelFilter.BOX;
            case "gaussian" -> new Gaussian(Gaussian.DEFAULT_STDDEV);
            default -> throw new IllegalArgumentException("unknown filter '" + name + "'; allowed: " + String.join(", ", NAMES));
        };
    }
}
