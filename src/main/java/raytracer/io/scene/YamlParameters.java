package raytracer.io.scene;

import org.yaml.snakeyaml.nodes.Node;
import raytracer.core.Factory;
import raytracer.core.ParameterException;
import raytracer.core.Parameters;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/**
 * The {@link Parameters} a registered type is made from: one mapping of the scene file, its keys
 * already checked against the type's, read through {@link YamlObject} so that a registered type's
 * messages are the reader's own. The types the reader makes itself also reach, through
 * {@link #context}, what the reader holds beside the values (the world, the meshes, the images).
 */
final class YamlParameters implements Parameters {
    private final YamlObject values;
    private final Object context;

    YamlParameters(YamlObject values, Object context) {
        this.values = values;
        this.context = context;
    }

    /** The mapping itself, for the reader's own types (lists of points, files). */
    YamlObject values() {
        return values;
    }

    /** What the reader gave for its own types to use, as {@code type}; a ClassCastException names a reader's mistake. */
    <C> C context(Class<C> type) {
        return type.cast(context);
    }

    /**
     * {@code factory}'s object: a value it refuses is the scene's error as the getter made it, and
     * an IllegalArgumentException of a constructor the scene's error at {@code where}, after
     * {@code prefix} (such as "sphere: ").
     */
    <T> T make(Factory<T> factory, Node where, String prefix) throws SceneException {
        try {
            return factory.make(this);
        } catch (ParameterException e) {
            throw e.getCause() instanceof SceneException s ? s : new SceneException(e.getMessage(), e);
        } catch (IllegalArgumentException e) {
            throw values.source().error(where, prefix + e.getMessage());
        }
    }

    /** The scene's error as a ParameterException, for a registered type to pass on. */
    private static ParameterException passed(SceneException e) {
        return new ParameterException(e.getMessage(), e);
    }

    /** A getter of YamlObject's, whose errors reach the type as ParameterExceptions. */
    @FunctionalInterface
    private interface Read<T> {
        T get() throws SceneException;
    }

    private static <T> T read(Read<T> read) throws ParameterException {
        try {
            return read.get();
        } catch (SceneException e) {
            throw passed(e);
        }
    }

    @Override
    public boolean has(String key) {
        return values.has(key);
    }

    @Override
    public String string(String key, String fallback) throws ParameterException {
        return read(() -> values.string(key, fallback));
    }

    @Override
    public double number(String key, double fallback) throws ParameterException {
        return read(() -> values.number(key, fallback));
    }

    @Override
    public double number(String key, double fallback, double min, boolean strict) throws ParameterException {
        return read(() -> values.number(key, fallback, min, strict));
    }

    @Override
    public int integer(String key, int fallback, int min, int max) throws ParameterException {
        return read(() -> values.integer(key, fallback, min, max));
    }

    @Override
    public boolean bool(String key, boolean fallback) throws ParameterException {
        return read(() -> values.bool(key, fallback));
    }

    @Override
    public Point3D point(String key, Point3D fallback) throws ParameterException {
        return read(() -> values.point(key, fallback));
    }

    @Override
    public Point3D requiredPoint(String key) throws ParameterException {
        return read(() -> values.requiredPoint(key));
    }

    @Override
    public Vector3D vector(String key, Vector3D fallback) throws ParameterException {
        return read(() -> values.vector(key, fallback));
    }

    @Override
    public Vector3D requiredVector(String key) throws ParameterException {
        return read(() -> values.requiredVector(key));
    }

    @Override
    public RGBColor color(String key, RGBColor fallback) throws ParameterException {
        return read(() -> values.color(key, fallback));
    }

    @Override
    public void checkEmission(String scaleKey, double scale, String colorKey, RGBColor color) throws ParameterException {
        read(() -> {
            values.checkEmission(scaleKey, scale, colorKey, color);
            return null;
        });
    }

    @Override
    public ParameterException error(String key, String message) {
        return passed(values.source().error(values.has(key) ? values.raw(key) : values.node(), message));
    }
}
