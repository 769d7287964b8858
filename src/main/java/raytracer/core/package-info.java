/**
 * The book's abstract types and the objects that tie them together (Suffern, chapters 3 and 14):
 * {@link raytracer.core.World}, {@link raytracer.core.ViewPlane}, {@link raytracer.core.ShadeRec},
 * {@link raytracer.core.GeometricObject}, {@link raytracer.core.Material}, {@link raytracer.core.BRDF},
 * {@link raytracer.core.BTDF}, {@link raytracer.core.Light}, {@link raytracer.core.Tracer},
 * {@link raytracer.core.Camera} and {@link raytracer.core.Sampler}. The families ({@code shapes},
 * {@code materials}, ...) implement these; the renderer sees only these. A worker's scratch
 * ({@link raytracer.core.WorkerScratch}) lives here too, with its {@link raytracer.core.RayTreePolicy}
 * (made from the render's {@link raytracer.core.RayTreeSettings}) and what the families need per
 * worker, such as the BVH traversal state ({@link raytracer.core.TraversalStack}). The
 * {@link raytracer.core.Registry} holds the named types that scene files and options choose from,
 * each added by a {@link raytracer.core.Registration} and made from the entry's
 * {@link raytracer.core.Parameters}, so that a family's new member registers itself.
 */
package raytracer.core;
