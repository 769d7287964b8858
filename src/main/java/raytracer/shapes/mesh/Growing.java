package raytracer.shapes.mesh;

import java.util.Arrays;

/**
 * Primitive arrays that grow while a mesh file is read, for the millions of values of a scanned
 * mesh. The first block doubles up to a block's size (a small mesh costs little); after it the
 * values go into further blocks of that size, so growing never copies what was read nor keeps old
 * copies: a doubling array holds up to twice its values and has copied them all once more by the
 * end. The one copy made is the exact array {@code toArray()} hands over at the end, after which
 * the buffer is empty.
 *
 * <p>A block takes {@value #BLOCK_BYTES} bytes with its array header: a whole number of the
 * collector's regions (G1's are 1 to 32 MiB, a power of two), where an array of 2^20 doubles and
 * its header would spill 16 bytes into a region of its own.
 */
public final class Growing {
    /** Bytes of a block, its array header (16 bytes on a 64-bit JVM) included: 8 MiB. */
    static final int BLOCK_BYTES = 8 << 20;
    static final int DOUBLES = (BLOCK_BYTES - 16) / 8;
    static final int FOURS = (BLOCK_BYTES - 16) / 4;
    private static final int FIRST = 1024;

    private Growing() {
    }

    /** Checks that {@code blocks} full blocks and a tail of {@code block} values each stay within one Java array. */
    private static int blocksFor(int blocks, int block) {
        if ((long) (blocks + 1) * block > Integer.MAX_VALUE - 8) {
            throw new IllegalStateException("more values than one Java array holds");
        }
        return blocks;
    }

    /** Growing doubles. */
    public static final class Doubles {
        /** Full blocks, then the one being filled. */
        private double[][] full = new double[0][];
        private double[] tail = new double[FIRST];
        private int tailSize;

        public int size() {
            return full.length * DOUBLES + tailSize;
        }

        public void add(double v) {
            if (tailSize == tail.length) {
                grow();
            }
            tail[tailSize++] = v;
        }

        /** Appends values[0 .. count). */
        public void addAll(double[] values, int count) {
            for (int at = 0; at < count; ) {
                if (tailSize == tail.length) {
                    grow();
                }
                int n = Math.min(count - at, tail.length - tailSize);
                System.arraycopy(values, at, tail, tailSize, n);
                tailSize += n;
                at += n;
            }
        }

        public double get(int i) {
            int inFull = full.length * DOUBLES;
            return i >= inFull ? tail[i - inFull] : full[i / DOUBLES][i % DOUBLES];
        }

        private void grow() {
            if (tail.length < DOUBLES) {
                tail = Arrays.copyOf(tail, Math.min(DOUBLES, 2 * tail.length));
            } else {
                full = Arrays.copyOf(full, blocksFor(full.length + 1, DOUBLES));
                full[full.length - 1] = tail;
                tail = new double[DOUBLES];
                tailSize = 0;
            }
        }

        /** Lets go of every value. */
        public void clear() {
            full = new double[0][];
            tail = new double[FIRST];
            tailSize = 0;
        }

        /** The values in one exact array, the buffer unchanged. */
        public double[] copy() {
            double[] out = new double[size()];
            for (int b = 0; b < full.length; b++) {
                System.arraycopy(full[b], 0, out, b * DOUBLES, DOUBLES);
            }
            System.arraycopy(tail, 0, out, full.length * DOUBLES, tailSize);
            return out;
        }

        /** The values in one exact array; the buffer lets go of its blocks and is empty after. */
        public double[] toArray() {
            double[] out = new double[size()];
            for (int b = 0; b < full.length; b++) {
                System.arraycopy(full[b], 0, out, b * DOUBLES, DOUBLES);
                full[b] = null; // garbage as soon as copied
            }
            System.arraycopy(tail, 0, out, full.length * DOUBLES, tailSize);
            full = new double[0][];
            tail = new double[FIRST];
            tailSize = 0;
            return out;
        }
    }

    /** Growing floats. */
    public static final class Floats {
        private float[][] full = new float[0][];
        private float[] tail = new float[FIRST];
        private int tailSize;

        public int size() {
            return full.length * FOURS + tailSize;
        }

        public void add(float v) {
            if (tailSize == tail.length) {
                grow();
            }
            tail[tailSize++] = v;
        }

        public float get(int i) {
            int inFull = full.length * FOURS;
            return i >= inFull ? tail[i - inFull] : full[i / FOURS][i % FOURS];
        }

        private void grow() {
            if (tail.length < FOURS) {
                tail = Arrays.copyOf(tail, Math.min(FOURS, 2 * tail.length));
            } else {
                full = Arrays.copyOf(full, blocksFor(full.length + 1, FOURS));
                full[full.length - 1] = tail;
                tail = new float[FOURS];
                tailSize = 0;
            }
        }

        /** The values in one exact array; the buffer lets go of its blocks and is empty after. */
        public float[] toArray() {
            float[] out = new float[size()];
            for (int b = 0; b < full.length; b++) {
                System.arraycopy(full[b], 0, out, b * FOURS, FOURS);
                full[b] = null;
            }
            System.arraycopy(tail, 0, out, full.length * FOURS, tailSize);
            full = new float[0][];
            tail = new float[FIRST];
            tailSize = 0;
            return out;
        }
    }

    /** Growing ints. */
    public static final class Ints {
        private int[][] full = new int[0][];
        private int[] tail = new int[FIRST];
        private int tailSize;

        public int size() {
            return full.length * FOURS + tailSize;
        }

        public void add(int v) {
            if (tailSize == tail.length) {
                grow();
            }
            tail[tailSize++] = v;
        }

        /** Appends values[0 .. count). */
        public void addAll(int[] values, int count) {
            for (int at = 0; at < count; ) {
                if (tailSize == tail.length) {
                    grow();
                }
                int n = Math.min(count - at, tail.length - tailSize);
                System.arraycopy(values, at, tail, tailSize, n);
                tailSize += n;
                at += n;
            }
        }

        /** Appends {@code count} copies of v. */
        public void fill(int v, int count) {
            for (int at = 0; at < count; ) {
                if (tailSize == tail.length) {
                    grow();
                }
                int n = Math.min(count - at, tail.length - tailSize);
                Arrays.fill(tail, tailSize, tailSize + n, v);
                tailSize += n;
                at += n;
            }
        }

        public int get(int i) {
            int inFull = full.length * FOURS;
            return i >= inFull ? tail[i - inFull] : full[i / FOURS][i % FOURS];
        }

        /** Sets value i, which must have been added. */
        public void set(int i, int v) {
            int inFull = full.length * FOURS;
            if (i >= inFull) {
                tail[i - inFull] = v;
            } else {
                full[i / FOURS][i % FOURS] = v;
            }
        }

        private void grow() {
            if (tail.length < FOURS) {
                tail = Arrays.copyOf(tail, Math.min(FOURS, 2 * tail.length));
            } else {
                full = Arrays.copyOf(full, blocksFor(full.length + 1, FOURS));
                full[full.length - 1] = tail;
                tail = new int[FOURS];
                tailSize = 0;
            }
        }

        /** The values in one exact array; the buffer lets go of its blocks and is empty after. */
        public int[] toArray() {
            int[] out = new int[size()];
            for (int b = 0; b < full.length; b++) {
                System.arraycopy(full[b], 0, out, b * FOURS, FOURS);
                full[b] = null;
            }
            System.arraycopy(tail, 0, out, full.length * FOURS, tailSize);
            full = new int[0][];
            tail = new int[FIRST];
            tailSize = 0;
            return out;
        }
    }
}
