import java.io.File;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Samples per second of two render jars, paired in one JVM: each jar is loaded in a class loader
 * of its own and the two render in turn (A B, then B A, ...), each render timed by the jar's own
 * --stats. On a machine whose speed swings within seconds, a pair of renders a second apart shares
 * the swing, where two JVMs a minute apart do not. Run by tools/sample-rate-paired.
 */
public final class SampleRatePaired {
    private static final int WARM_UP_PAIRS = 3;

    public static void main(String[] args) throws Exception {
        if (args.length < 3) {
            System.err.println("usage: SampleRatePaired OLD.jar NEW.jar PAIRS [SCENE] [SPP]");
            System.exit(2);
        }
        String[] jars = {args[0], args[1]};
        int pairs = Integer.parseInt(args[2]);
        String scene = args.length > 3 ? args[3] : "scenes/arealight-spheres.yaml";
        int spp = args.length > 4 ? Integer.parseInt(args[4]) : 64;
        Method[] run = new Method[2];
        for (int i = 0; i < 2; i++) {
            URLClassLoader loader = new URLClassLoader(new URL[] {new File(jars[i]).toURI().toURL()},
                                                       ClassLoader.getPlatformClassLoader());
            run[i] = loader.loadClass("raytracer.cli.RenderCommand").getMethod("run", PrintWriter.class, String[].class);
        }
        File out = File.createTempFile("sample-rate-paired", ".pfm");
        out.deleteOnExit();
        // two renders a call: the second is timed, so each call's scene loading is left out
        String[] renderArgs = {scene, "-o", out.getPath(), "--width", "512", "--height", "512", "--spp", Integer.toString(spp),
                               "--threads", "2", "--repeat", "2", "-q", "--stats"};
        Pattern timed = Pattern.compile("render 2 of 2: ([0-9.]+) s");
        double samples = 512.0 * 512 * spp;
        List<List<Double>> rates = List.of(new ArrayList<>(), new ArrayList<>());
        for (int p = -WARM_UP_PAIRS; p < pairs; p++) {
            StringBuilder line = new StringBuilder(p < 0 ? "warm-up" : "pair " + (p + 1));
            for (int k = 0; k < 2; k++) {
                int i = (p & 1) == 0 ? k : 1 - k;
                StringWriter err = new StringWriter();
                Object code = run[i].invoke(null, new PrintWriter(err, true), renderArgs);
                Matcher m = timed.matcher(err.toString());
                if (!code.equals(0) || !m.find()) {
                    throw new IllegalStateException(jars[i] + " failed: " + err);
                }
                double rate = samples / Double.parseDouble(m.group(1)) / 1e6;
                if (p >= 0) {
                    rates.get(i).add(rate);
                }
                line.append(String.format(" %s %.2f", i == 0 ? "old" : "new", rate));
            }
            System.out.println(line + " M samples/s");
        }
        List<Double> ratios = new ArrayList<>();
        for (int p = 0; p < pairs; p++) {
            ratios.add(rates.get(1).get(p) / rates.get(0).get(p));
        }
        System.out.printf("new over old: median %.3f, quartiles %.3f and %.3f over %d pairs%n",
                          quantile(ratios, 0.5), quantile(ratios, 0.25), quantile(ratios, 0.75), pairs);
        System.out.printf("medians: old %.2f, new %.2f M samples/s%n", quantile(rates.get(0), 0.5), quantile(rates.get(1), 0.5));
    }

    /** The value at fraction q of the sorted values (the nearest rank below). */
    private static double quantile(List<Double> values, double q) {
        List<Double> sorted = new ArrayList<>(values);
        Collections.sort(sorted);
        return sorted.get((int) (q * (sorted.size() - 1)));
    }
}
