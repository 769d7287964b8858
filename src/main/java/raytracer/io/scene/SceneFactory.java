package raytracer.io.scene;

import raytracer.core.Factory;
import raytracer.core.ParameterException;
import raytracer.core.Parameters;

/**
 * A built-in type that the reader makes from more than typed values: a triangle's list of points,
 * a mesh's file, an image, an area light's visible shape in the world. It is registered as any
 * other type, and reads its mapping and the reader's context through {@link YamlParameters}.
 */
@FunctionalInterface
interface SceneFactory<T> extends Factory<T> {
    T make(YamlParameters p) throws SceneException;

    @Override
    default T make(Parameters p) throws ParameterException {
        try {
            // the reader makes every type from its own parameters
            return make((YamlParameters) p);
        } catch (SceneException e) {
            throw new ParameterException(e.getMessage(), e);
        }
    }

    /** {@code factory} as the Factory it is, for a registration (a method reference needs the type). */
    static <T> Factory<T> of(SceneFactory<T> factory) {
        return factory;
    }
}
