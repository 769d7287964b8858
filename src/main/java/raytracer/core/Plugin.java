package raytracer.core;

import java.util.Set;

/**
 * One registered type: its name, its own keys, and how to make it (a {@link Factory}, or the
 * family's own form: a {@link CameraFactory}, a sampler's constructor). Mitsuba 3 calls these
 * plugins.
 */
public record Plugin<F>(String name, Set<String> keys, F make) {
    public Plugin {
        if (name == null || name.isBlank() || make == null) {
            throw new IllegalArgumentException("a type is registered with a name and a way to make it, got name '" + name
                                               + "' and " + make);
        }
        keys = Set.copyOf(keys);
    }
}
