package raytracer.accel;

/**
 * Boxes as the BVH stores them, six floats each (x0, y0, z0, x1, y1, z1) at {@code 6 i}, rounded
 * outward from doubles so that a box never shrinks; and what the median builders compute on them.
 */
final class FloatBoxes {
    private FloatBoxes() {
    }

    /** The largest float not above d (-infinity below the float range). */
    static float roundDown(double d) {
        float f = (float) d;
        return f > d ? Math.nextDown(f) : f;
    }

    /** The smallest float not below d. */
    static float roundUp(double d) {
        float f = (float) d;
        return f < d ? Math.nextUp(f) : f;
    }

    /**
     * A float not above d, at most a few float ulps below, without {@link #roundDown}'s branch on
     * which way the cast went (taken at random, for the millions of triangle boxes): the float
     * nearest to d is within 2^-24 |d| of it (or 2^-150 below the normal range), so stepping down
     * by 2^-22 |d| + 2^-149 first is enough.
     */
    static float roundDownLoosely(double d) {
        return (float) Math.min(d - (Math.abs(d) * 0x1p-22 + Float.MIN_VALUE), Float.MAX_VALUE);
    }

    /** A float not below d, as {@link #roundDownLoosely}. */
    static float roundUpLoosely(double d) {
        return (float) Math.max(d + (Math.abs(d) * 0x1p-22 + Float.MIN_VALUE), -Float.MAX_VALUE);
    }

    /** Boxes given as doubles (six each), rounded outward exactly. */
    static float[] roundOutward(double[] boxes) {
        float[] out = new float[boxes.length];
        for (int i = 0; i < boxes.length; i += 6) {
            for (int k = 0; k < 3; k++) {
                out[i + k] = roundDown(boxes[i + k]);
                out[i + 3 + k] = roundUp(boxes[i + 3 + k]);
            }
        }
        return out;
    }

    /** The union of boxes from .. to - 1, written to {@code out[at .. at + 6)}. */
    static void union(float[] boxes, int from, int to, float[] out, int at) {
        float x0 = Float.POSITIVE_INFINITY;
        float y0 = Float.POSITIVE_INFINITY;
        float z0 = Float.POSITIVE_INFINITY;
        float x1 = Float.NEGATIVE_INFINITY;
        float y1 = Float.NEGATIVE_INFINITY;
        float z1 = Float.NEGATIVE_INFINITY;
        // comparisons rather than Math.min/max: a running extreme rarely changes, so the branches
        // predict well, where Math.min's NaN-and-zero handling costs a blend sequence per value
        for (int p = 6 * from; p < 6 * to; p += 6) {
            float v = boxes[p];
            x0 = v < x0 ? v : x0;
            v = boxes[p + 1];
            y0 = v < y0 ? v : y0;
            v = boxes[p + 2];
            z0 = v < z0 ? v : z0;
            v = boxes[p + 3];
            x1 = v > x1 ? v : x1;
            v = boxes[p + 4];
            y1 = v > y1 ? v : y1;
            v = boxes[p + 5];
            z1 = v > z1 ? v : z1;
        }
        out[at] = x0;
        out[at + 1] = y0;
        out[at + 2] = z0;
        out[at + 3] = x1;
        out[at + 4] = y1;
        out[at + 5] = z1;
    }

    /** The axis (0, 1, 2) along which the box at {@code box[at .. at + 6)} is longest; ties go to the first. */
    static int longestAxis(float[] box, int at) {
        float ex = box[at + 3] - box[at];
        float ey = box[at + 4] - box[at + 1];
        float ez = box[at + 5] - box[at + 2];
        return ex >= ey && ex >= ez ? 0 : (ey >= ez ? 1 : 2);
    }

    /** Twice the centroid of box i on the axis: the builders' sort key (the same order, one operation less). */
    static float centroidKey(float[] boxes, int i, int axis) {
        return boxes[6 * i + axis] + boxes[6 * i + 3 + axis];
    }
}
