package raytracer.image;

import java.util.Locale;
import java.util.Optional;

/**
 * How a PNG's 8-bit code values encode radiance: through the sRGB transfer curve, or as the clamped
 * radiance itself, as the report's renderer wrote its images (darker, more contrasted). PFM output
 * is linear either way.
 */
public enum DisplayEncoding {
    SRGB, LINEAR;

    /** The names a scene file and the command line use, for messages. */
    public static final String NAMES = "linear, srgb";

    /** True when code values go through the sRGB curve. */
    public boolean srgbCurve() {
        return this == SRGB;
    }

    /** The encoding called {@code name} ({@code srgb} or {@code linear}), if there is one. */
    public static Optional<DisplayEncoding> named(String name) {
        for (DisplayEncoding e : values()) {
            if (e.name().toLowerCase(Locale.ROOT).equals(name)) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
    }
}
