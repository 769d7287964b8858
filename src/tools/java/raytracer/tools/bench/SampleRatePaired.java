package raytracer.tools.bench;

import java.io.File;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Samples per second of render jars paired in one JVM: each jar is loaded in a class loader of its
 * own and they render in turn, the order rotating pair by pair (A B, then B A, ...), each render
 * timed by the jar's own --stats. On a machine whose speed swings within seconds, renders a second
 * apart share the swing, where two JVMs a minute apart do not. Run by the rate-paired workload of
 * tools/bench/ab, which reads the lines "round N: A rate B rate ..." and computes the medians.
 *
 *   SampleRatePaired PAIRS SCENE SPP THREADS JAR JAR... [-- render options]
 */
public final class SampleRatePaired {
    private static final int WARM_UP_PAIRS = 3;
    private static final int SIZE = 512;

    public static void main(String[] args) throws Exception {
        int dashes = Arrays.asList(args).indexOf("--");
        List<String> words = Arrays.asList(args).subList(0, dashes < 0 ? args.length : dashes);
        List<String> extra = dashes < 0 ? List.of() : Arrays.asList(args).subList(dashes + 1, args.length);
        if (words.size() < 6) {
            System.err.println("usage: SampleRatePaired PAIRS SCENE SPP THREADS JAR JAR... [-- render options]");
            System.exit(2);
        }
        int pairs = Integer.parseInt(words.get(0));
        String scene = words.get(1);
        int spp = Integer.parseInt(words.get(2));
        String threads = words.get(3);
        List<String> jars = words.subList(4, words.size());
        int n = jars.size();
        Method[] run = new Method[n];
        for (int i = 0; i < n; i++) {
            // the platform loader as parent: each jar sees its own classes only, not the other's
            URLClassLoader loader = new URLClassLoader(new URL[] {new File(jars.get(i)).toURI().toURL()},
                                                       ClassLoader.getPlatformClassLoader());
            run[i] = loader.loadClass("raytracer.cli.RenderCommand").getMethod("run", PrintWriter.class, String[].class);
        }
        File out = File.createTempFile("sample-rate-paired", ".pfm");
        out.deleteOnExit();
        // two renders a call: the second is timed, so each call's scene loading is left out
        List<String> renderArgs = new ArrayList<>(List.of(scene, "-o", out.getPath(), "--width", Integer.toString(SIZE),
                                                          "--height", Integer.toString(SIZE), "--spp", Integer.toString(spp),
                                                          "--threads", threads, "--repeat", "2", "-q", "--stats"));
        renderArgs.addAll(extra);
        Pattern timed = Pattern.compile("render 2 of 2: ([0-9.]+) s");
        double samples = (double) SIZE * SIZE * spp;
        for (int p = -WARM_UP_PAIRS; p < pairs; p++) {
            double[] rates = new double[n];
            for (int k = 0; k < n; k++) {
                int i = Math.floorMod(k + p, n);
                StringWriter err = new StringWriter();
                Object code = run[i].invoke(null, new PrintWriter(err, true), renderArgs.toArray(String[]::new));
                Matcher m = timed.matcher(err.toString());
                if (!code.equals(0) || !m.find()) {
                    throw new IllegalStateException(jars.get(i) + " failed: " + err);
                }
                rates[i] = samples / Double.parseDouble(m.group(1)) / 1e6;
            }
            StringBuilder line = new StringBuilder(p < 0 ? "warm-up:" : "round " + (p + 1) + ":");
            for (int i = 0; i < n; i++) {
                line.append(String.format(Locale.ROOT, " %c %.3f", (char) ('A' + i), rates[i]));
            }
            System.out.println(line);
        }
    }
}
