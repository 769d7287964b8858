package raytracer.core;

/**
 * Where a worker's hit records come from. The renderer reuses one per recursion depth; the
 * allocation study (docs/performance.md, "The allocation study") also runs the way most Java ports
 * of the book work, a new record, with the vectors and scratch rays it owns, for every ray traced.
 */
public enum ShadeRecSupply {
    /** One record per recursion depth per worker, overwritten by every ray at that depth. */
    REUSE,
    /** A new record for every ray traced: the study's allocating alternative. */
    FRESH
}
