package raytracer.core;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.function.Function;
import java.util.function.Supplier;

/**
 * The named types that scene files and options choose from, by family, as Mitsuba 3's plugin
 * manager: each is added by a {@link Registration}, so that a new sampler, light or material is a
 * class and one line of a services file rather than an edit of every reader's switch. The scene
 * reader and the command line find every type here, built-in or not, and list the registered
 * names in their messages and help. Made once and never changed.
 */
public final class Registry {
    private final Plugins<Supplier<Sampler>> samplers;
    private final Plugins<Factory<PixelFilter>> filters;
    private final Plugins<CameraFactory> cameras;
    private final Plugins<Factory<Light>> lights;
    private final Plugins<Factory<Light>> ambients;
    private final Plugins<Factory<GeometricObject>> objects;
    private final Plugins<Factory<Material>> materials;
    private final Plugins<Factory<Texture>> textures;
    private final Plugins<Function<List<GeometricObject>, GeometricObject>> accelerations;

    private Registry(Builder b) {
        samplers = new Plugins<>(b.samplers);
        filters = new Plugins<>(b.filters);
        cameras = new Plugins<>(b.cameras);
        lights = new Plugins<>(b.lights);
        ambients = new Plugins<>(b.ambients);
        objects = new Plugins<>(b.objects);
        materials = new Plugins<>(b.materials);
        textures = new Plugins<>(b.textures);
        accelerations = new Plugins<>(b.accelerations);
    }

    /** The registry of every registration on the class path, made when first asked for. */
    public static Registry standard() {
        return Standard.REGISTRY;
    }

    /** Holds the standard registry, so that it is made on first use and once (the JVM's class initialisation). */
    private static final class Standard {
        static final Registry REGISTRY = load();

        private static Registry load() {
            // the loader of this class, not the thread's: a copy of the classes in a loader of its own finds its own registrations
            ClassLoader loader = Registration.class.getClassLoader();
            Registry registry = of(ServiceLoader.load(Registration.class, loader));
            if (registry.samplers.names().isEmpty()) {
                // without the built-in types every scene would fail with a misleading "unknown sampler"
                throw new IllegalStateException("no types are registered: META-INF/services/" + Registration.class.getName()
                                                + " is not on the class path of " + loader);
            }
            return registry;
        }
    }

    /** A registry of {@code registrations}, run in order; a name registered twice in a family is an IllegalStateException. */
    public static Registry of(Iterable<? extends Registration> registrations) {
        Builder builder = new Builder();
        for (Registration registration : registrations) {
            builder.current = registration.getClass().getName();
            registration.register(builder);
        }
        return new Registry(builder);
    }

    public Plugins<Supplier<Sampler>> samplers() {
        return samplers;
    }

    public Plugins<Factory<PixelFilter>> filters() {
        return filters;
    }

    public Plugins<CameraFactory> cameras() {
        return cameras;
    }

    public Plugins<Factory<Light>> lights() {
        return lights;
    }

    public Plugins<Factory<Light>> ambients() {
        return ambients;
    }

    public Plugins<Factory<GeometricObject>> objects() {
        return objects;
    }

    public Plugins<Factory<Material>> materials() {
        return materials;
    }

    public Plugins<Factory<Texture>> textures() {
        return textures;
    }

    public Plugins<Function<List<GeometricObject>, GeometricObject>> accelerations() {
        return accelerations;
    }

    /** The tables being filled while the registrations run. */
    private static final class Builder implements Registrar {
        final Map<String, Plugin<Supplier<Sampler>>> samplers = new LinkedHashMap<>();
        final Map<String, Plugin<Factory<PixelFilter>>> filters = new LinkedHashMap<>();
        final Map<String, Plugin<CameraFactory>> cameras = new LinkedHashMap<>();
        final Map<String, Plugin<Factory<Light>>> lights = new LinkedHashMap<>();
        final Map<String, Plugin<Factory<Light>>> ambients = new LinkedHashMap<>();
        final Map<String, Plugin<Factory<GeometricObject>>> objects = new LinkedHashMap<>();
        final Map<String, Plugin<Factory<Material>>> materials = new LinkedHashMap<>();
        final Map<String, Plugin<Factory<Texture>>> textures = new LinkedHashMap<>();
        final Map<String, Plugin<Function<List<GeometricObject>, GeometricObject>>> accelerations = new LinkedHashMap<>();
        /** The registration running, for the message about a name registered twice. */
        String current;

        private <F> void add(Map<String, Plugin<F>> family, String what, String name, Set<String> keys, F make) {
            Plugin<F> plugin = new Plugin<>(name, keys, make);
            if (family.putIfAbsent(name, plugin) != null) {
                throw new IllegalStateException(what + " '" + name + "' is registered twice; the second time by " + current);
            }
        }

        @Override
        public void sampler(String name, Supplier<Sampler> make) {
            add(samplers, "sampler", name, Set.of(), make);
        }

        @Override
        public void filter(String name, Set<String> keys, Factory<PixelFilter> make) {
            add(filters, "filter", name, keys, make);
        }

        @Override
        public void camera(String name, Set<String> keys, CameraFactory make) {
            add(cameras, "camera type", name, keys, make);
        }

        @Override
        public void light(String name, Set<String> keys, Factory<Light> make) {
            add(lights, "light type", name, keys, make);
        }

        @Override
        public void ambient(String name, Set<String> keys, Factory<Light> make) {
            add(ambients, "ambient type", name, keys, make);
        }

        @Override
        public void object(String name, Set<String> keys, Factory<GeometricObject> make) {
            add(objects, "object type", name, keys, make);
        }

        @Override
        public void material(String name, Set<String> keys, Factory<Material> make) {
            add(materials, "material type", name, keys, make);
        }

        @Override
        public void texture(String name, Set<String> keys, Factory<Texture> make) {
            add(textures, "texture type", name, keys, make);
        }

        @Override
        public void acceleration(String name, Function<List<GeometricObject>, GeometricObject> build) {
            add(accelerations, "acceleration", name, Set.of(), build);
        }
    }
}
