package raytracer.core;

/**
 * Adds named types to the {@link Registry}: a sampler, a light, an object, a material, ... by the
 * name a scene file or an option gives it. A registration is found by {@link java.util.ServiceLoader}:
 * its class is public, has a public constructor without parameters, and its binary name is a line
 * of {@code META-INF/services/raytracer.core.Registration} (in this project,
 * src/main/resources/META-INF/services/raytracer.core.Registration). The built-in types register
 * this way too, so a new type is read, listed and checked as they are without editing a reader.
 */
@FunctionalInterface
public interface Registration {
    void register(Registrar registrar);
}
