package raytracer.samplers;

import java.util.List;
import raytracer.core.Sampler;

/** Sampler patterns by the names scene files and options use. */
public final class Samplers {
    private static final List<String> NAMES = List.of("regular", "random", "jittered", "n-rooks", "multi-jittered", "hammersley");

    private Samplers() {
    }

    public static List<String> names() {
        return NAMES;
    }

    public static Sampler byName(String name) {
        return switch (name) {
            case "regular" -> new Regular();
            case "random" -> new PureRandom();
            case "jittered" -> new Jittered();
            case "n-rooks" -> new NRooks();
            case "multi-jittered" -> new MultiJittered();
            case "hammersley" -> new Hammersley();
            default -> throw new IllegalArgumentException(
                "unknown sampler '" + name + "'; allowed: " + String.join(", ", NAMES));
        };
    }
}
