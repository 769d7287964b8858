/**
 * Numbers the renderer is made of. {@link raytracer.math.Vector3D}, {@link raytracer.math.Point3D},
 * {@link raytracer.math.Normal}, {@link raytracer.math.RGBColor}, {@link raytracer.math.Matrix4} and
 * {@link raytracer.math.BBox} are immutable values used to describe a scene. {@link raytracer.math.MutableVec3},
 * {@link raytracer.math.MutableRgb}, {@link raytracer.math.Ray} and {@link raytracer.math.Rng} are the mutable
 * scratch that the per-ray path overwrites in place, so that tracing a ray allocates nothing; so are
 * {@link raytracer.math.SlabRay} and {@link raytracer.math.ShearedRay}, what the slab test and the
 * watertight triangle test precompute from a ray before they test it against many boxes or triangles.
 */
package raytracer.math;
