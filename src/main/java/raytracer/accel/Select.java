package raytracer.accel;

/**
 * Quickselect (Hoare's FIND, 1961) on an index array keyed by one centroid coordinate: afterwards
 * order[k] holds the element a full sort would put there, with no larger key before it and no
 * smaller key after it. Expected O(n); median-of-three pivots avoid the sorted-input worst case.
 */
final class Select {
    private Select() {
    }

    static void nth(int[] order, double[] centroids, int axis, int from, int to, int k) {
        int lo = from;
        int hi = to - 1;
        while (hi > lo) {
            int mid = (lo + hi) >>> 1;
            // median of three to the middle, as pivot
            if (key(order, centroids, axis, mid) < key(order, centroids, axis, lo)) {
                swap(order, mid, lo);
            }
            if (key(order, centroids, axis, hi) < key(order, centroids, axis, lo)) {
                swap(order, hi, lo);
            }
            if (key(order, centroids, axis, hi) < key(order, centroids, axis, mid)) {
                swap(order, hi, mid);
            }
            double pivot = key(order, centroids, axis, mid);
            int i = lo;
            int j = hi;
            // Hoare partition: equal keys stop both scans, so runs of equal keys still split evenly
            while (i <= j) {
                while (key(order, centroids, axis, i) < pivot) {
                    i++;
                }
                while (key(order, centroids, axis, j) > pivot) {
                    j--;
                }
                if (i <= j) {
                    swap(order, i, j);
                    i++;
                    j--;
                }
            }
            if (k <= j) {
                hi = j;
            } else if (k >= i) {
                lo = i;
            } else {
                return; // j < k < i: k holds the pivot value
            }
        }
    }

    private static double key(int[] order, double[] centroids, int axis, int i) {
        return centroids[3 * order[i] + axis];
    }

    private static void swap(int[] order, int a, int b) {
        int t = order[a];
        order[a] = order[b];
        order[b] = t;
    }
}
