package raytracer.accel;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.LongVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import raytracer.math.SlabRay;

/**
 * {@link NodeTest} with the Vector API (JEP 508, jdk.incubator.vector): each plane of the four
 * boxes is one load of four floats, widened to four doubles, and the slab test runs on the four
 * lanes at once. Lane by lane it is {@link SlabRay#entryBits}'s arithmetic: the same IEEE
 * operations on the same doubles, and extremes that agree with the bit-pattern extremes there
 * (Math.max's order puts -0.0 below 0.0, and no NaN arises off the parallel case, which is left to
 * the scalar test), so the keys are the same bits.
 */
final class VectorNodeTest implements NodeTest {
    private static final VectorSpecies<Float> FLOATS = FloatVector.SPECIES_128;
    private static final VectorSpecies<Double> DOUBLES = DoubleVector.SPECIES_256;
    private static final LongVector LANE_NUMBERS = LongVector.fromArray(LongVector.SPECIES_256, new long[] {0, 1, 2, 3}, 0);
    private final ScalarNodeTest scalar = new ScalarNodeTest();

    @Override
    public void keys(SlabRay ray, float[] bounds, int at, long tMaxBits, long[] keys) {
        if (ray.parallel()) {
            scalar.keys(ray, bounds, at, tMaxBits, keys);
            return;
        }
        DoubleVector t0 = DoubleVector.zero(DOUBLES);
        DoubleVector t1 = DoubleVector.broadcast(DOUBLES, Double.longBitsToDouble(tMaxBits));
        for (int axis = 0; axis < 3; axis++) {
            double origin = ray.origin(axis);
            DoubleVector near = plane(bounds, at + ray.nearPlane(axis)).sub(origin).mul(ray.inverse(axis));
            DoubleVector far = plane(bounds, at + ray.farPlane(axis)).sub(origin).mul(ray.farInverse(axis)).add(0.0);
            t0 = t0.max(near);
            t1 = t1.min(far);
        }
        VectorMask<Double> missed = t0.compare(VectorOperators.GT, t1);
        t0.blend(Double.POSITIVE_INFINITY, missed).reinterpretAsLongs().and(~3L).or(LANE_NUMBERS).intoArray(keys, 0);
    }

    /** One plane of the four boxes, as doubles. */
    private static DoubleVector plane(float[] bounds, int at) {
        return (DoubleVector) FloatVector.fromArray(FLOATS, bounds, at).convertShape(VectorOperators.F2D, DOUBLES, 0);
    }

    @Override
    public String name() {
        return "vector";
    }
}
