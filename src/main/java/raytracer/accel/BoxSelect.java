package raytracer.accel;

/**
 * Selection over primitives stored as float boxes (six per primitive) with their ids beside them,
 * keyed by the box's centroid on one axis: afterwards position k holds the primitive a full sort
 * would put there, with no larger key before it and no smaller key after it. Boxes move with their
 * ids, so the passes read memory in order.
 *
 * <p>Large ranges use Floyd and Rivest's SELECT (CACM 18(3), 1975): the k-th element of a window
 * of about n^(2/3) elements around k is found first, recursively, and is nearly the k-th of the
 * whole range, so one partition pass around it leaves only a sliver to finish; about 1.5 n
 * comparisons for a median instead of about 2.75 n for quickselect with a median-of-three pivot
 * (Hoare's FIND, 1961), which finishes the smaller ranges.
 */
final class BoxSelect {
    /** Ranges this short are finished by insertion sort. */
    private static final int SMALL = 12;
    /** Ranges longer than this pick their pivot from a recursively selected window (Floyd and Rivest use 600). */
    private static final int WINDOWED = 600;

    private BoxSelect() {
    }

    /** Selects within positions [from, to) so that position k holds its sorted element. */
    static void nth(float[] boxes, int[] ids, int axis, int from, int to, int k) {
        select(boxes, ids, axis, from, to - 1, k);
    }

    private static void select(float[] boxes, int[] ids, int axis, int lo, int hi, int k) {
        while (hi - lo >= SMALL) {
            if (hi - lo > WINDOWED) {
                // a window around k whose k-th element lies within a few standard deviations of
                // the range's k-th, with the sizes of Floyd and Rivest's algorithm 489
                double n = hi - lo + 1;
                double i = k - lo + 1;
                double z = Math.log(n);
                double s = 0.5 * Math.exp(2 * z / 3);
                double sd = 0.5 * Math.sqrt(z * s * (n - s) / n) * Math.signum(i - n / 2);
                int windowLo = (int) Math.max(lo, Math.floor(k - i * s / n + sd));
                int windowHi = (int) Math.min(hi, Math.floor(k + (n - i) * s / n + sd));
                select(boxes, ids, axis, windowLo, windowHi, k);
            } else {
                // median of three to k, as pivot
                int mid = (lo + hi) >>> 1;
                if (key(boxes, axis, mid) < key(boxes, axis, lo)) {
                    swap(boxes, ids, mid, lo);
                }
                if (key(boxes, axis, hi) < key(boxes, axis, lo)) {
                    swap(boxes, ids, hi, lo);
                }
                if (key(boxes, axis, hi) < key(boxes, axis, mid)) {
                    swap(boxes, ids, hi, mid);
                }
                swap(boxes, ids, mid, k);
            }
            long split = partition(boxes, ids, axis, lo, hi, key(boxes, axis, k));
            int i = (int) (split >>> 32);
            int j = (int) split;
            if (k <= j) {
                hi = j;
            } else if (k >= i) {
                lo = i;
            } else {
                return; // j < k < i: k holds the pivot value
            }
        }
        insertionSort(boxes, ids, axis, lo, hi);
    }

    /**
     * Hoare's partition of [lo, hi] around {@code pivot}: equal keys stop both scans, so runs of
     * equal keys still split evenly. Returns the final scan positions i (high 32 bits) and j (low):
     * keys at or before j are not above the pivot, keys at or after i are not below it. A method of
     * its own, like {@link #insertionSort}, so that the JIT compiles each loop early and on its own.
     */
    private static long partition(float[] boxes, int[] ids, int axis, int lo, int hi, float pivot) {
        int i = lo;
        int j = hi;
        while (i <= j) {
            while (key(boxes, axis, i) < pivot) {
                i++;
            }
            while (key(boxes, axis, j) > pivot) {
                j--;
            }
            if (i <= j) {
                swap(boxes, ids, i, j);
                i++;
                j--;
            }
        }
        return (long) i << 32 | (j & 0xffffffffL);
    }

    private static void insertionSort(float[] boxes, int[] ids, int axis, int lo, int hi) {
        for (int i = lo + 1; i <= hi; i++) {
            for (int j = i; j > lo && key(boxes, axis, j) < key(boxes, axis, j - 1); j--) {
                swap(boxes, ids, j, j - 1);
            }
        }
    }

    /** Twice the centroid on the axis: the same order, one operation less. */
    private static float key(float[] boxes, int axis, int i) {
        return boxes[6 * i + axis] + boxes[6 * i + 3 + axis];
    }

    private static void swap(float[] boxes, int[] ids, int a, int b) {
        int id = ids[a];
        ids[a] = ids[b];
        ids[b] = id;
        int pa = 6 * a;
        int pb = 6 * b;
        for (int c = 0; c < 6; c++) {
            float t = boxes[pa + c];
            boxes[pa + c] = boxes[pb + c];
            boxes[pb + c] = t;
        }
    }
}
