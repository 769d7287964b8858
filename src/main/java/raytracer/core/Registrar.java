package raytracer.core;

import java.util.List;
import java.util.Set;
import java.util.function.Function;
import java.util.function.Supplier;

/**
 * What a {@link Registration} registers with: one method per family, each taking the name the
 * scene file or option uses, the keys of the type's own (the reader adds the keys every member of
 * the family has, said below, and refuses any other), and how to make it. A name is registered once
 * per family; the registry lists the names in the order they were registered.
 */
public interface Registrar {
    /** A sample pattern: {@code image: {sampler: NAME}} in a scene and {@code --sampler NAME}. */
    void sampler(String name, Supplier<Sampler> make);

    /**
     * A pixel filter: {@code image: {filter: NAME}} and {@code --filter NAME}. Its keys sit in the
     * scene's {@code image} section beside {@code filter}; {@code --filter} makes it from
     * {@link Parameters#NONE}, with its defaults.
     */
    void filter(String name, Set<String> keys, Factory<PixelFilter> make);

    /** A camera: {@code camera: {type: NAME}}; every camera has {@code eye}, {@code look-at} and {@code up}. */
    void camera(String name, Set<String> keys, CameraFactory make);

    /** A light of the {@code lights} list: {@code {type: NAME}}; every light has {@code shadows}. */
    void light(String name, Set<String> keys, Factory<Light> make);

    /**
     * The world's ambient light, which every material asks for its ambient term (Suffern, chapter
     * 14): {@code ambient: {type: NAME}}. The built-in one is {@code constant}, and the key
     * {@code type} is read only once there is another to choose.
     */
    void ambient(String name, Set<String> keys, Factory<Light> make);

    /**
     * An object of the {@code objects} list: {@code {type: NAME}}; every object has {@code name},
     * {@code material}, {@code transform} and {@code casts-shadows}, which the reader applies.
     */
    void object(String name, Set<String> keys, Factory<GeometricObject> make);

    /** A material of the {@code materials} map: {@code {type: NAME}}. */
    void material(String name, Set<String> keys, Factory<Material> make);

    /** A texture, the value of a material's {@code texture} key: {@code {type: NAME}}. */
    void texture(String name, Set<String> keys, Factory<Texture> make);

    /**
     * A search structure for the world's objects: {@code --accel NAME}. {@code build} makes the
     * aggregate over the bounded objects (at least one; planes stay outside it), or returns null to
     * leave them a plain list.
     */
    void acceleration(String name, Function<List<GeometricObject>, GeometricObject> build);
}
