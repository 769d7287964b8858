package raytracer.accel;

import raytracer.math.SlabRay;

/** {@link NodeTest} lane by lane: four slab tests, each without a branch on the box ({@link SlabRay#entryBits}). */
final class ScalarNodeTest implements NodeTest {
    @Override
    public void keys(SlabRay ray, float[] bounds, int at, long tMaxBits, long[] keys) {
        keys[0] = ray.entryBits(bounds, at, tMaxBits) & ~3L;
        keys[1] = ray.entryBits(bounds, at + 1, tMaxBits) & ~3L | 1;
        keys[2] = ray.entryBits(bounds, at + 2, tMaxBits) & ~3L | 2;
        keys[3] = ray.entryBits(bounds, at + 3, tMaxBits) & ~3L | 3;
    }

    @Override
    public String name() {
        return "scalar";
    }
}
