package raytracer.samplers;

import java.util.List;
import raytracer.core.Registry;
import raytracer.core.Sampler;

/** Sampler patterns by the names scene files and options use: those of the {@link Registry}. */
public final class Samplers {
    private Samplers() {
    }

    /** The names, in the order they were registered. */
    public static List<String> names() {
        return Registry.standard().samplers().names();
    }

    /** The name of a sampler's pattern, as {@link #byName} takes it. */
    public static String nameOf(Sampler sampler) {
        for (String name : names()) {
            if (byName(name).getClass() == sampler.getClass()) {
                return name;
            }
        }
        return sampler.getClass().getSimpleName();
    }

    public static Sampler byName(String name) {
        return Registry.standard().samplers().find(name)
            .orElseThrow(() -> new IllegalArgumentException("unknown sampler '" + name + "'; allowed: " + String.join(", ", names())))
            .make().get();
    }
}
