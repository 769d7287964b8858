package raytracer.accel;

/**
 * Selection over primitives stored as float boxes (six per primitive) with their ids beside them,
 * in the order of the report's sort: by the centroid on one axis ({@link FloatBoxes#centroidKey}),
 * ties by id, so that no two primitives are equal and the median is one primitive. Afterwards
 * position k holds the primitive a full sort would put there, with only smaller ones before it
 * and larger ones after. Boxes move with their ids, so the passes read memory in order, and so
 * does {@code carried}, three ints per primitive or null (a mesh's vertex indices, which thus
 * reach the leaf order without a copy).
 *
 * <p>Large ranges use Floyd and Rivest's SELECT (CACM 18(3), 1975): the k-th element of a window
 * of about n^(2/3) elements around k is found first, recursively, and is nearly the k-th of the
 * whole range, so one partition around it leaves only a sliver to finish; about 1.5 n comparisons
 * for a median instead of about 2.75 n for quickselect with a median-of-three pivot (Hoare's FIND,
 * 1961), which finishes the smaller ranges.
 */
final class BoxSelect {
    /** Ranges this short are finished by insertion sort. */
    private static final int SMALL = 12;
    /** Ranges longer than this pick their pivot from a recursively selected window (Floyd and Rivest use 600). */
    private static final int WINDOWED = 600;

    private BoxSelect() {
    }

    /** Selects within positions from .. to - 1 so that position k holds its sorted element. */
    static void nth(float[] boxes, int[] ids, int[] carried, int axis, int from, int to, int k) {
        select(boxes, ids, carried, axis, from, to - 1, k);
    }

    /** Sorts positions from .. to - 1 (a leaf's few primitives). */
    static void sort(float[] boxes, int[] ids, int[] carried, int axis, int from, int to) {
        insertionSort(boxes, ids, carried, axis, from, to - 1);
    }

    private static void select(float[] boxes, int[] ids, int[] carried, int axis, int lo, int hi, int k) {
        while (hi - lo >= SMALL) {
            int pivot;
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
                select(boxes, ids, carried, axis, windowLo, windowHi, k);
                pivot = k;
            } else {
                // the median of the first, middle and last elements
                int mid = (lo + hi) >>> 1;
                if (before(boxes, ids, axis, mid, lo)) {
                    swap(boxes, ids, carried, mid, lo);
                }
                if (before(boxes, ids, axis, hi, lo)) {
                    swap(boxes, ids, carried, hi, lo);
                }
                if (before(boxes, ids, axis, hi, mid)) {
                    swap(boxes, ids, carried, hi, mid);
                }
                pivot = mid;
            }
            float pivotKey = FloatBoxes.centroidKey(boxes, pivot, axis);
            int pivotId = ids[pivot];
            int j = partition(boxes, ids, carried, axis, lo, hi, pivotKey, pivotId);
            if (k <= j) {
                hi = j;
            } else if (k == j + 1 && ids[k] == pivotId) {
                return; // the pivot ended between the two parts, at k
            } else {
                lo = j + 1;
            }
        }
        insertionSort(boxes, ids, carried, axis, lo, hi);
    }

    /**
     * Hoare's partition of positions lo .. hi around the pivot, an element among them given by
     * its key and id: returns j such that no element at or before j comes after the pivot and
     * none after j comes before it; the pivot itself is at j + 1 or in one of the two parts.
     */
    private static int partition(float[] boxes, int[] ids, int[] carried, int axis, int lo, int hi, float pivotKey, int pivotId) {
        // a method of its own, like insertionSort, so that the JIT compiles each loop early. The
        // scans need no bounds test: the pivot, or an element swapped past, stops each (a bounds
        // test that is rarely false became a trap, and JFR showed the first pass deoptimised)
        int i = lo;
        int j = hi;
        while (i <= j) {
            while (before(FloatBoxes.centroidKey(boxes, i, axis), ids[i], pivotKey, pivotId)) {
                i++;
            }
            while (before(pivotKey, pivotId, FloatBoxes.centroidKey(boxes, j, axis), ids[j])) {
                j--;
            }
            if (i <= j) {
                swap(boxes, ids, carried, i, j);
                i++;
                j--;
            }
        }
        return j;
    }

    private static void insertionSort(float[] boxes, int[] ids, int[] carried, int axis, int lo, int hi) {
        for (int i = lo + 1; i <= hi; i++) {
            for (int j = i; j > lo && before(boxes, ids, axis, j, j - 1); j--) {
                swap(boxes, ids, carried, j, j - 1);
            }
        }
    }

    /** True when the primitive at position a comes before the one at position b. */
    private static boolean before(float[] boxes, int[] ids, int axis, int a, int b) {
        return before(FloatBoxes.centroidKey(boxes, a, axis), ids[a], FloatBoxes.centroidKey(boxes, b, axis), ids[b]);
    }

    /** The report's order: by key, ties by id. */
    static boolean before(float keyA, int idA, float keyB, int idB) {
        // & and | rather than && and ||: a tie is rare, and the JIT compiles a rarely taken
        // branch as a trap, whose first use sends the pass back to the interpreter
        return keyA < keyB | (keyA == keyB & idA < idB);
    }

    /** Exchanges the primitives at positions a and b: boxes, ids and carried ints. */
    static void swap(float[] boxes, int[] ids, int[] carried, int a, int b) {
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
        if (carried != null) {
            for (int c = 0; c < 3; c++) {
                int t = carried[3 * a + c];
                carried[3 * a + c] = carried[3 * b + c];
                carried[3 * b + c] = t;
            }
        }
    }
}
