package raytracer.io.obj;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The argument of a texture statement ({@code map_Kd}, {@code bump}, ...): options, each with its
 * arguments, before or after the file name, and the file name, which is what remains, spaces
 * included. Options are those of the MTL specification (Wavefront, Appendix B1 of the Advanced
 * Visualizer manual) and the extensions exporters write ({@code -colorspace}); the numbers taken
 * by {@code -o}, {@code -s} and {@code -t} (1 to 3) and {@code -mm} (1 or 2) are the numbers that
 * follow. A dash-word that is no option is part of the name.
 */
record TextureMap(String file, double bumpScale) {
    private static final Pattern TOKEN = Pattern.compile("\\S+");
    private static final Pattern NUMBER = Pattern.compile(ObjPatterns.NUMBER);

    /** The file and {@code -bm} of {@code text}; a value that is not a number leaves the scale at 1. */
    static TextureMap parse(String text) {
        Matcher token = TOKEN.matcher(text);
        Matcher number = NUMBER.matcher("");
        double bumpScale = 1;
        int nameStart = -1;
        int nameEnd = -1;
        while (token.find()) {
            int[] counts = arguments(token.group());
            if (counts == null) {
                nameStart = nameStart < 0 ? token.start() : nameStart;
                nameEnd = token.end();
                continue;
            }
            String option = token.group();
            for (int k = 0; k < counts[1]; k++) {
                if (!token.find()) {
                    break;
                }
                if (k >= counts[0] && !number.reset(token.group()).matches()) {
                    // not one of the optional numbers: read it again as what it is
                    token.region(token.start(), text.length());
                    break;
                }
                if (option.equals("-bm") && number.reset(token.group()).matches()) {
                    bumpScale = Double.parseDouble(token.group());
                }
            }
        }
        return new TextureMap(nameStart < 0 ? "" : text.substring(nameStart, nameEnd), bumpScale);
    }

    /** The option's least and most arguments, or null if {@code word} is no option. */
    private static int[] arguments(String word) {
        return switch (word) {
            case "-blendu", "-blendv", "-bm", "-boost", "-cc", "-clamp", "-imfchan", "-texres", "-type", "-colorspace" -> new int[] {1, 1};
            case "-mm" -> new int[] {1, 2};
            case "-o", "-s", "-t" -> new int[] {1, 3};
            default -> null;
        };
    }
}
