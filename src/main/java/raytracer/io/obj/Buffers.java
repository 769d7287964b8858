package raytracer.io.obj;

import java.util.Arrays;

/** Growable primitive arrays: a million vertices are a million doubles, not a million objects. */
final class Buffers {
    private Buffers() {
    }

    static final class Doubles {
        double[] data;
        int size;

        Doubles() {
            this(1024);
        }

        Doubles(int capacity) {
            data = new double[Math.max(16, capacity)];
        }

        /** Appends a[0 .. count). */
        void addAll(double[] a, int count) {
            if (size + count > data.length) {
                data = Arrays.copyOf(data, Math.max(2 * data.length, size + count));
            }
            System.arraycopy(a, 0, data, size, count);
            size += count;
        }

        void add(double v) {
            if (size == data.length) {
                data = Arrays.copyOf(data, 2 * size);
            }
            data[size++] = v;
        }

        double[] toArray() {
            return Arrays.copyOf(data, size);
        }
    }

    static final class Floats {
        float[] data = new float[1024];
        int size;

        void add(float v) {
            if (size == data.length) {
                data = Arrays.copyOf(data, 2 * size);
            }
            data[size++] = v;
        }
    }

    static final class Ints {
        int[] data;
        int size;

        Ints() {
            this(1024);
        }

        Ints(int capacity) {
            data = new int[Math.max(16, capacity)];
        }

        /** Appends a[0 .. count). */
        void addAll(int[] a, int count) {
            if (size + count > data.length) {
                data = Arrays.copyOf(data, Math.max(2 * data.length, size + count));
            }
            System.arraycopy(a, 0, data, size, count);
            size += count;
        }

        void add(int v) {
            if (size == data.length) {
                data = Arrays.copyOf(data, 2 * size);
            }
            data[size++] = v;
        }

        /** Appends {@code count} copies of v. */
        void fill(int v, int count) {
            for (int i = 0; i < count; i++) {
                add(v);
            }
        }

        int[] toArray() {
            return Arrays.copyOf(data, size);
        }
    }
}
