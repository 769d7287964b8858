package raytracer;
import org.openjdk.jmh.annotations.Benchmark;
public class SmokeBenchmark { @Benchmark public double x() { return Math.sqrt(2); } }
