package raytracer.io.obj;

import java.util.Arrays;

/** Growable primitive arrays: a million vertices are a million doubles, not a million objects. */
final class Buffers {
    private Buffers() {
    }

    static final class Doubles {
        double[] data = new double[1024];
        int size;

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
        int[] data = new int[1024];
        int size;

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
