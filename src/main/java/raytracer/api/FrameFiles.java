package raytracer.api;

import java.nio.file.Path;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The names of an animation's files: {@code -o} as a pattern holding one {@code %d} (or
 * {@code %04d}) for the frame number. The Spark job names its frames alike.
 */
public final class FrameFiles {
    /** One printf integer conversion, with an optional width, zero-padded or not (a zero flag needs a width: %0d throws). */
    private static final Pattern FRAME = Pattern.compile("%(0?[1-9])?d");

    private FrameFiles() {
    }

    /** The default pattern beside the working directory: {@code <scene name>-%04d.png}. */
    public static String defaultPattern(Path scene) {
        String still = OutputFile.defaultFor(scene).toString();
        return still.substring(0, still.length() - ".png".length()).replace("%", "%%") + "-%04d.png";
    }

    /**
     * Why {@code pattern} cannot name the frames, or null: it must hold exactly one {@code %d},
     * {@code %0Nd} or {@code %Nd}, and any other {@code %} doubled.
     */
    public static String whyNotPattern(String pattern) {
        int conversions = 0;
        for (int i = 0; i < pattern.length(); i++) {
            if (pattern.charAt(i) != '%') {
                continue;
            }
            if (pattern.startsWith("%%", i)) {
                i++;
                continue;
            }
            Matcher m = FRAME.matcher(pattern).region(i, pattern.length());
            if (!m.lookingAt()) {
                return "a % in it must be %d, %04d (the frame number) or %% (a percent sign)";
            }
            conversions++;
            i = m.end() - 1;
        }
        return conversions == 1 ? null : "it must hold one %d or %04d for the frame number, e.g. out/frame-%04d.png; it has "
                                         + conversions;
    }

    /** The file of frame {@code frame}. */
    public static Path name(String pattern, int frame) {
        return Path.of(format(pattern, frame));
    }

    /** The name of frame {@code frame}: {@code pattern} (checked by {@link #whyNotPattern}) with the number put in. */
    public static String format(String pattern, int frame) {
        return String.format(Locale.ROOT, pattern, frame);
    }
}
