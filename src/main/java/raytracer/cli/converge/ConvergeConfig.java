package raytracer.cli.converge;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import raytracer.core.Sampler;
import raytracer.samplers.Samplers;

/**
 * One curve of the convergence benchmark: the settings that differ from the scene's. Null means
 * the scene's own value. Written on the command line as {@code key=value} pairs joined by commas,
 * a value may list alternatives joined by '/', which spell out every combination:
 * {@code sampler=random/multi-jittered,light-samples=1/16} is four configurations.
 */
record ConvergeConfig(String label, String sampler, Integer lightSamples, Double cutoff) {
    static final Set<String> KEYS = Set.of("sampler", "light-samples", "cutoff", "label");

    /** The scene as it is. */
    static final ConvergeConfig SCENE = new ConvergeConfig(null, null, null, null);

    /** Every configuration a {@code --config} value spells; IllegalArgumentException says what is wrong with it. */
    static List<ConvergeConfig> parse(String text) {
        Map<String, String[]> values = new LinkedHashMap<>();
        for (String pair : text.split(",", -1)) {
            int eq = pair.indexOf('=');
            String key = eq < 0 ? pair.strip() : pair.substring(0, eq).strip();
            if (eq < 0 || !KEYS.contains(key)) {
                throw new IllegalArgumentException("--config '" + text + "': expected key=value pairs joined by commas, with keys "
                                                   + String.join(", ", new TreeSet<>(KEYS)) + "; got '" + pair + "'");
            }
            if (values.put(key, pair.substring(eq + 1).strip().split("/", -1)) != null) {
                throw new IllegalArgumentException("--config '" + text + "': '" + key + "' given twice");
            }
        }
        List<ConvergeConfig> configs = new ArrayList<>(List.of(SCENE));
        for (Map.Entry<String, String[]> entry : values.entrySet()) {
            List<ConvergeConfig> next = new ArrayList<>();
            for (ConvergeConfig c : configs) {
                for (String value : entry.getValue()) {
                    next.add(c.with(entry.getKey(), value, text));
                }
            }
            configs = next;
        }
        return configs;
    }

    private ConvergeConfig with(String key, String value, String text) {
        String where = "--config '" + text + "': ";
        return switch (key) {
            case "sampler" -> {
                if (!Samplers.names().contains(value)) {
                    throw new IllegalArgumentException(where + "unknown sampler '" + value + "'; allowed: "
                                                       + String.join(", ", Samplers.names()));
                }
                yield new ConvergeConfig(label, value, lightSamples, cutoff);
            }
            case "light-samples" -> {
                int n = parseInt(value, where + "light-samples");
                if (n < 1 || n > Sampler.MAX_SAMPLES) {
                    throw new IllegalArgumentException(where + "light-samples must be 1 to " + Sampler.MAX_SAMPLES + ", got " + n);
                }
                yield new ConvergeConfig(label, sampler, n, cutoff);
            }
            case "cutoff" -> {
                double c = parseDouble(value, where + "cutoff");
                if (!(c >= 0 && c < 1)) {
                    throw new IllegalArgumentException(where + "cutoff must be in [0, 1), got " + value);
                }
                yield new ConvergeConfig(label, sampler, lightSamples, c);
            }
            default -> {
                if (value.isBlank()) {
                    throw new IllegalArgumentException(where + "the label is empty");
                }
                yield new ConvergeConfig(value, sampler, lightSamples, cutoff);
            }
        };
    }

    private static int parseInt(String value, String what) {
        try {
            return Integer.parseInt(value);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + " must be a whole number, got '" + value + "'");
        }
    }

    private static double parseDouble(String value, String what) {
        try {
            return Double.parseDouble(value);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + " must be a number, got '" + value + "'");
        }
    }

    /**
     * The curve's name: the label if given, else the settings that make it as the renderer uses
     * them (the sampler's name, the area lights' sample count after rounding, a cutoff if any).
     */
    String name(String samplerName, String lightSamplesUsed, double cutoffUsed) {
        if (label != null) {
            return label;
        }
        return samplerName + ", " + lightSamplesUsed + " light sample" + (lightSamplesUsed.equals("1") ? "" : "s")
               + (cutoffUsed > 0 ? ", cutoff " + cutoffUsed : "");
    }
}
