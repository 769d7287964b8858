package raytracer.image;

/**
 * Linear radiance to display values: multiply by the exposure, clamp to [0, 1], then apply the sRGB
 * transfer function (IEC 61966-2-1) and round to 8 bits. The report's renderer wrote the clamped
 * radiance as the code value without that curve; {@link #toByte(double, double, boolean)} can do the
 * same, to compare with its images.
 */
public final class ToneMap {
    private ToneMap() {
    }

    /** The sRGB opto-electronic transfer function for a linear value in [0, 1]. */
    public static double srgbEncode(double linear) {
        return linear <= 0.0031308 ? 12.92 * linear : 1.055 * Math.pow(linear, 1 / 2.4) - 0.055;
    }

    /** The inverse transfer function: an sRGB-encoded value in [0, 1] back to linear. */
    public static double srgbDecode(double v) {
        return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
    }

    /** An 8-bit sRGB code value for a linear radiance, after exposure and clamping. */
    public static int toByte(double linear, double exposure) {
        return toByte(linear, exposure, true);
    }

    /** As {@link #toByte(double, double)}; without {@code srgb} the clamped value is the code (gamma 1). */
    public static int toByte(double linear, double exposure, boolean srgb) {
        double v = linear * exposure;
        if (!(v > 0)) {
            return 0; // also maps NaN to black rather than to an arbitrary code
        }
        if (v >= 1) {
            return 255;
        }
        return (int) Math.round(255 * (srgb ? srgbEncode(v) : v));
    }
}
