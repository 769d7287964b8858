package raytracer.tools.studies;

import java.io.BufferedOutputStream;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.zip.GZIPInputStream;

/**
 * A large mesh with the shape of a scanned one (docs/performance.md, "Meshes of tens of millions
 * of triangles"): every triangle of an OBJ file (the dragon) cut into k^2 by a k-step grid on its
 * edges, the points on a shared edge shared, so that the result is as watertight as the input and
 * its BVH is the scan's, only deeper. Written as OBJ text ({@code .obj}) or binary little-endian
 * PLY ({@code .ply}).
 *
 *   java -cp build/libs/render-tools.jar raytracer.tools.studies.BigMesh IN.obj[.gz] TRIANGLES OUT.obj|OUT.ply
 *
 * (tools/studies/scale-study/big-mesh runs it on the dragon.)
 *
 * k is the whole number whose k^2 x 871,414 (the dragon's) comes nearest TRIANGLES, so that
 * 4, 16 and 32 million give k = 2, 4, 6: 3.5, 13.9 and 31.4 million.
 */
public final class BigMesh {
    public static void main(String[] args) throws IOException {
        if (args.length != 3) {
            System.err.println("usage: BigMesh IN.obj[.gz] TRIANGLES OUT.obj|OUT.ply");
            System.exit(2);
        }
        Path in = Path.of(args[0]);
        long target;
        try {
            target = Long.parseLong(args[1]);
        } catch (NumberFormatException e) {
            System.err.println("BigMesh: TRIANGLES must be a whole number, e.g. 4000000; got " + args[1]);
            System.exit(2);
            return;
        }
        Path out = Path.of(args[2]);
        double[][] p = new double[1][];
        int[][] t = new int[1][];
        read(in, p, t);
        int triangles = t[0].length / 3;
        int k = (int) Math.round(Math.sqrt((double) target / triangles));
        k = Math.max(1, k);
        long made = (long) triangles * k * k;
        if (made > Integer.MAX_VALUE / 3) {
            throw new IllegalArgumentException(made + " triangles are more than one mesh holds");
        }
        Grid grid = new Grid(p[0], t[0], k);
        grid.build();
        System.err.printf("%s: %d triangles cut %d x %d: %d vertices, %d triangles%n", in, triangles, k, k, grid.vertices,
                          grid.triangleCount);
        // written beside it and renamed when whole, so that a killed run leaves no truncated mesh that
        // the scale study, which reuses what it finds, would then measure
        Path partial = out.resolveSibling(out.getFileName() + ".partial");
        if (out.toString().endsWith(".ply")) {
            grid.writePly(partial);
        } else {
            grid.writeObj(partial);
        }
        Files.move(partial, out, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
    }

    /** Positions and triangles (0-based) of an OBJ file's v and f lines, faces fanned. */
    private static void read(Path file, double[][] positions, int[][] triangles) throws IOException {
        double[] p = new double[3 << 16];
        int[] t = new int[3 << 16];
        int np = 0;
        int nt = 0;
        try (InputStream raw = Files.newInputStream(file);
             InputStream stream = file.toString().endsWith(".gz") ? new GZIPInputStream(raw, 1 << 16) : raw;
             BufferedReader r = new BufferedReader(new InputStreamReader(stream, StandardCharsets.ISO_8859_1), 1 << 16)) {
            String line;
            while ((line = r.readLine()) != null) {
                String[] w = line.trim().split("\\s+");
                if (w[0].equals("v")) {
                    if (np + 3 > p.length) {
                        p = Arrays.copyOf(p, 2 * p.length);
                    }
                    for (int i = 1; i <= 3; i++) {
                        p[np++] = Double.parseDouble(w[i]);
                    }
                } else if (w[0].equals("f")) {
                    int first = index(w[1], np / 3);
                    for (int i = 2; i + 1 < w.length; i++) {
                        if (nt + 3 > t.length) {
                            t = Arrays.copyOf(t, 2 * t.length);
                        }
                        t[nt++] = first;
                        t[nt++] = index(w[i], np / 3);
                        t[nt++] = index(w[i + 1], np / 3);
                    }
                }
            }
        }
        positions[0] = Arrays.copyOf(p, np);
        triangles[0] = Arrays.copyOf(t, nt);
    }

    private static int index(String corner, int vertices) {
        int slash = corner.indexOf('/');
        int i = Integer.parseInt(slash < 0 ? corner : corner.substring(0, slash));
        return i > 0 ? i - 1 : vertices + i;
    }

    /** The k-step grid on every triangle, edge points shared between the triangles of an edge. */
    private static final class Grid {
        private final double[] p;
        private final int[] t;
        private final int k;
        private final Map<Long, Integer> edges = new HashMap<>();
        private double[] positions;
        private int[] triangles;
        int vertices;
        int triangleCount;

        Grid(double[] p, int[] t, int k) {
            this.p = p;
            this.t = t;
            this.k = k;
        }

        void build() {
            int source = t.length / 3;
            long edgeCount = (long) source * 3 / 2 + 16;
            long estimate = p.length / 3 + edgeCount * (k - 1) + (long) source * (k - 1) * (k - 2) / 2 + 16;
            positions = new double[(int) (3 * estimate)];
            System.arraycopy(p, 0, positions, 0, p.length);
            vertices = p.length / 3;
            triangles = new int[3 * source * k * k];
            int[][] id = new int[k + 1][k + 1];
            for (int f = 0; f < source; f++) {
                int a = t[3 * f];
                int b = t[3 * f + 1];
                int c = t[3 * f + 2];
                // grid point (i, j) = a + (i / k)(b - a) + (j / k)(c - a)
                for (int i = 0; i <= k; i++) {
                    for (int j = 0; i + j <= k; j++) {
                        id[i][j] = point(a, b, c, i, j);
                    }
                }
                for (int i = 0; i < k; i++) {
                    for (int j = 0; i + j < k; j++) {
                        add(id[i][j], id[i + 1][j], id[i][j + 1]);
                        if (i + j < k - 1) {
                            add(id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]);
                        }
                    }
                }
            }
        }

        private void add(int x, int y, int z) {
            triangles[3 * triangleCount] = x;
            triangles[3 * triangleCount + 1] = y;
            triangles[3 * triangleCount + 2] = z;
            triangleCount++;
        }

        /** The vertex of grid point (i, j): a corner, a point of an edge (shared), or an inner point (new). */
        private int point(int a, int b, int c, int i, int j) {
            if (i == 0 && j == 0) {
                return a;
            }
            if (i == k) {
                return b;
            }
            if (j == k) {
                return c;
            }
            if (j == 0) {
                return onEdge(a, b, i);
            }
            if (i == 0) {
                return onEdge(a, c, j);
            }
            if (i + j == k) {
                return onEdge(b, c, j);
            }
            return added(a, b, c, i, j);
        }

        /** Point m of k along the edge from u to v, made once per edge in the direction of its lower vertex. */
        private int onEdge(int u, int v, int m) {
            int lo = Math.min(u, v);
            int hi = Math.max(u, v);
            long key = (long) lo << 32 | hi;
            Integer first = edges.get(key);
            if (first == null) {
                first = vertices;
                for (int s = 1; s < k; s++) {
                    append(lo, hi, (double) s / k);
                }
                edges.put(key, first);
            }
            int step = u == lo ? m : k - m;
            return first + step - 1;
        }

        private int added(int a, int b, int c, int i, int j) {
            int v = vertices;
            ensure();
            double s = (double) i / k;
            double r = (double) j / k;
            for (int d = 0; d < 3; d++) {
                positions[3 * v + d] = p[3 * a + d] + s * (p[3 * b + d] - p[3 * a + d]) + r * (p[3 * c + d] - p[3 * a + d]);
            }
            vertices++;
            return v;
        }

        private void append(int lo, int hi, double s) {
            ensure();
            for (int d = 0; d < 3; d++) {
                positions[3 * vertices + d] = p[3 * lo + d] + s * (p[3 * hi + d] - p[3 * lo + d]);
            }
            vertices++;
        }

        private void ensure() {
            if (3 * vertices + 3 > positions.length) {
                positions = Arrays.copyOf(positions, positions.length + positions.length / 2);
            }
        }

        void writeObj(Path out) throws IOException {
            try (OutputStream o = new BufferedOutputStream(Files.newOutputStream(out), 1 << 20)) {
                StringBuilder s = new StringBuilder(1 << 16);
                for (int v = 0; v < vertices; v++) {
                    s.append("v ").append((float) positions[3 * v]).append(' ').append((float) positions[3 * v + 1]).append(' ')
                     .append((float) positions[3 * v + 2]).append('\n');
                    flush(s, o);
                }
                for (int f = 0; f < triangleCount; f++) {
                    s.append("f ").append(triangles[3 * f] + 1).append(' ').append(triangles[3 * f + 1] + 1).append(' ')
                     .append(triangles[3 * f + 2] + 1).append('\n');
                    flush(s, o);
                }
                o.write(s.toString().getBytes(StandardCharsets.US_ASCII));
            }
        }

        private static void flush(StringBuilder s, OutputStream o) throws IOException {
            if (s.length() > 60_000) {
                o.write(s.toString().getBytes(StandardCharsets.US_ASCII));
                s.setLength(0);
            }
        }

        void writePly(Path out) throws IOException {
            try (OutputStream o = new BufferedOutputStream(Files.newOutputStream(out), 1 << 20)) {
                o.write(("ply\nformat binary_little_endian 1.0\ncomment made by BigMesh\nelement vertex " + vertices
                         + "\nproperty float x\nproperty float y\nproperty float z\nelement face " + triangleCount
                         + "\nproperty list uchar int vertex_indices\nend_header\n").getBytes(StandardCharsets.US_ASCII));
                ByteBuffer b = ByteBuffer.allocate(1 << 16).order(ByteOrder.LITTLE_ENDIAN);
                for (int v = 0; v < vertices; v++) {
                    if (b.remaining() < 12) {
                        o.write(b.array(), 0, b.position());
                        b.clear();
                    }
                    b.putFloat((float) positions[3 * v]).putFloat((float) positions[3 * v + 1]).putFloat((float) positions[3 * v + 2]);
                }
                for (int f = 0; f < triangleCount; f++) {
                    if (b.remaining() < 13) {
                        o.write(b.array(), 0, b.position());
                        b.clear();
                    }
                    b.put((byte) 3).putInt(triangles[3 * f]).putInt(triangles[3 * f + 1]).putInt(triangles[3 * f + 2]);
                }
                o.write(b.array(), 0, b.position());
            }
        }
    }
}
