/**
 * The allocation study (docs/performance.md, "The allocation study"): the renderer's way, one
 * mutable {@link raytracer.core.ShadeRec} per recursion depth and mutable vectors, measured against
 * the two ways most Java ports of Suffern's book take. {@link raytracer.study.AllocationMode} names
 * the three: {@code reuse} (the renderer), {@code fresh} (a new hit record for every ray) and
 * {@code immutable} (new hit records, then immutable vector and colour records, a new one for every
 * step, through shading and light sampling: the textbook's Java). The immutable path is the
 * smallest that renders the study's scenes, written in that style: Matte, Phong and a mirror,
 * point and directional lights, ambient light and Whitted's tracer. It searches with the renderer's
 * own BVHs and two-phase hits, so every mode computes the same numbers in the same order and the
 * images are bitwise equal; only what is allocated differs.
 * Its classes are the book's, named {@code Immutable...} ({@link raytracer.study.ImmutableWhitted},
 * {@link raytracer.study.ImmutablePhong}, ...) so that none shares a name with the renderer's.
 *
 * <p>Nothing in the renderer uses this package: it exists for the study's benchmark and test.
 */
package raytracer.study;
