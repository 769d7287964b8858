package raytracer.core;

import raytracer.math.Ray;

/**
 * An object with its own coordinate system (an {@code Instance}): completion of a hit inside it
 * needs the ray in its local space and a way to carry the result back out.
 */
public interface LocalFrame {

    /** Writes the parent-space ray {@code in} into {@code out} in local coordinates. */
    void toLocal(Ray in, Ray out);

    /** Transforms the completed hit in {@code sr} (point, error bound, normals) to parent space. */
    void toWorld(ShadeRec sr);
}
