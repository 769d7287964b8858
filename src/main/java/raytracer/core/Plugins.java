package raytracer.core;

import java.util.Collections;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/** The registered types of one family, by name, in the order they were registered. */
public final class Plugins<F> {
    private final Map<String, Plugin<F>> byName;

    Plugins(Map<String, Plugin<F>> byName) {
        this.byName = Collections.unmodifiableMap(new LinkedHashMap<>(byName));
    }

    /** The names, in the order they were registered (as {@code --help} lists them). */
    public List<String> names() {
        return List.copyOf(byName.keySet());
    }

    public Optional<Plugin<F>> find(String name) {
        return Optional.ofNullable(byName.get(name));
    }

    /** Every type's keys together (the image section's keys of the filters). */
    public Set<String> keys() {
        Set<String> all = new HashSet<>();
        byName.values().forEach(p -> all.addAll(p.keys()));
        return Set.copyOf(all);
    }

    /** The first registered type that has {@code key}, if any. */
    public Optional<Plugin<F>> withKey(String key) {
        return byName.values().stream().filter(p -> p.keys().contains(key)).findFirst();
    }
}
