package raytracer.samplers;

import java.util.List;
import raytracer.core.Sampler;

/** Sampler patterns by the names scene files and options use. */
public final class Samplers {
    private static final List<String> NAMES = List.of("regular", "random", "jittered", "n-rooks", "multi-jittered",
                                                       "correlated-multi-jittered", "hammersley", "sobol");

    private Samplers() {
    }

    public static List<String> names() {
        return NAMES;
    }

    /** The name of a sampler's pattern, as {@link #byName} takes it. */
    public static String nameOf(Sampler sampler) {
        for (String name : NAMES) {
            if (byName(name).getClass() == sampler.getClass()) {
                return name;
            }
        }
        return sampler.getClass().getSimpleName();
    }

    public static Sampler byName(String name) {
        return switch (name) {
            case "regular" -> new Regular();
            case "random" -> new PureRandom();
            case "jittered" -> new Jittered();
            case "n-rooks" -> new NRooks();
            case "multi-jittered" -> new MultiJittered();
            case "correlated-multi-jittered" -> new CorrelatedMultiJittered();
            case "hammersley" -> new Hammersley();
            case "sobol" -> new Sobol();
            default -> throw new IllegalArgumentException(
                "unknown sampler '" + name + "'; allowed: " + String.join(", ", NAMES));
        };
    }
}
