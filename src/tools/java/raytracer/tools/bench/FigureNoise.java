package raytracer.tools.bench;

import java.io.DataInputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Whether a change moved an image by more than its noise: for three linear PFMs of one scene, A
 * (old code, seed 1), B (old code, seed 2) and C (new code, seed 1), prints the relative RMSE of
 * B and of C against A, their ratio, the relative difference of the means of C and A, and how many
 * pixels changed at all. A ratio near 1 with a mean within the noise is "unchanged within noise";
 * a scene without noise (B equal to A) shows its changes as pixels. Run by the figures workload of
 * tools/bench/ab. The PFMs are read here, not by the jars' own code, so that the reader is the same
 * whichever jars are compared.
 */
public final class FigureNoise {
    public static void main(String[] args) throws IOException {
        float[] a = read(Path.of(args[0]));
        float[] b = read(Path.of(args[1]));
        float[] c = read(Path.of(args[2]));
        double noise = relativeRmse(b, a);
        double change = relativeRmse(c, a);
        double meanA = mean(a);
        double meanB = mean(b);
        double meanC = mean(c);
        int changed = 0;
        for (int i = 0; i < a.length; i += 3) {
            if (a[i] != c[i] || a[i + 1] != c[i + 1] || a[i + 2] != c[i + 2]) {
                changed++;
            }
        }
        System.out.printf("noise %.4f  change %.4f  ratio %s  mean %+.4f%% (seeds %+.4f%%)  pixels changed %d of %d%n",
                          noise, change, noise > 0 ? String.format("%.3f", change / noise) : "-",
                          100 * (meanC - meanA) / meanA, 100 * (meanB - meanA) / meanA, changed, a.length / 3);
    }

    private static double relativeRmse(float[] x, float[] reference) {
        double squared = 0;
        double sum = 0;
        for (int i = 0; i < x.length; i++) {
            double d = x[i] - reference[i];
            squared += d * d;
            sum += (double) reference[i] * reference[i];
        }
        return Math.sqrt(squared / sum);
    }

    private static double mean(float[] x) {
        double sum = 0;
        for (float v : x) {
            sum += v;
        }
        return sum / x.length;
    }

    private static float[] read(Path file) throws IOException {
        try (DataInputStream in = new DataInputStream(Files.newInputStream(file))) {
            String magic = line(in);
            String[] size = line(in).trim().split("\\s+");
            double scale = Double.parseDouble(line(in).trim());
            int channels = magic.equals("PF") ? 3 : 1;
            int n = Integer.parseInt(size[0]) * Integer.parseInt(size[1]) * channels;
            byte[] bytes = in.readNBytes(4 * n);
            ByteBuffer buffer = ByteBuffer.wrap(bytes).order(scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
            float[] values = new float[n];
            for (int i = 0; i < n; i++) {
                values[i] = buffer.getFloat();
            }
            return values;
        }
    }

    private static String line(DataInputStream in) throws IOException {
        StringBuilder s = new StringBuilder();
        int c;
        while ((c = in.read()) != -1 && c != '\n') {
            s.append((char) c);
        }
        return s.toString();
    }
}
