package raytracer.core;

import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/** Follows one ray into the world and returns the radiance along it (Suffern, chapter 3). */
public interface Tracer {

    /**
     * Writes the radiance arriving along {@code ray} at recursion {@code depth} into {@code out}.
     * Depth 0 is a camera ray, and only the renderer traces at depth 0 (a material's rays go one
     * deeper than its hit): {@link World#hit} relies on it to search a camera ray's tile's objects
     * only ({@link WorkerScratch#cameraRayObjects}).
     */
    void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out);

    /**
     * False when rays below the camera's are not traced into the scene at all (the ray-cast
     * tracer returns black for them): no object is then seen except by camera and shadow rays.
     */
    default boolean tracesSecondaryRays() {
        return true;
    }
}
