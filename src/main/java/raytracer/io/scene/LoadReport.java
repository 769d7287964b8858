package raytracer.io.scene;

import java.util.ArrayList;
import java.nio.file.Path;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * What loading a scene found besides the scene itself: how long its steps took (parsing a mesh;
 * when the scene is prepared, building its BVH or reading it from the mesh cache), figures of what
 * was built (a mesh's triangles and vertices) and warnings (something odd but harmless, such as a
 * missing texture, or a stale cache), and the files it reads. Filled by the readers while loading and by the loaded
 * meshes while the scene is prepared, read by the command line after each.
 */
public final class LoadReport {
    private final Map<String, Long> timings = new LinkedHashMap<>();
    private final Map<String, Long> prepareTimings = new LinkedHashMap<>();
    private final List<String> statistics = new ArrayList<>();
    private final List<String> warnings = new ArrayList<>();
    private final Set<Path> inputs = new LinkedHashSet<>();

    /** Notes how long a step took; a step recorded twice adds up. */
    void recordTiming(String step, long nanos) {
        timings.merge(step, nanos, Long::sum);
    }

    /** Notes how long a step of preparing the scene took (building a mesh's BVH, reading it from the cache). */
    void recordPrepareTiming(String step, long nanos) {
        prepareTimings.merge(step, nanos, Long::sum);
    }

    void addStatistic(String line) {
        statistics.add(line);
    }

    void addWarning(String warning) {
        warnings.add(warning);
    }

    /** Notes a file the scene reads (the scene file, a mesh, a material library, an image). */
    void addInput(Path file) {
        inputs.add(file.toAbsolutePath().normalize());
    }

    /** Steps and their durations in nanoseconds, in the order they were first recorded. */
    public Map<String, Long> timings() {
        return Collections.unmodifiableMap(timings);
    }

    /** Steps of {@link raytracer.core.World#prepare} that the loaded objects took, in nanoseconds, in order. */
    public Map<String, Long> prepareTimings() {
        return Collections.unmodifiableMap(prepareTimings);
    }

    /** One line per figure, for --stats. */
    public List<String> statistics() {
        return List.copyOf(statistics);
    }

    public List<String> warnings() {
        return List.copyOf(warnings);
    }

    /**
     * Every file the scene read or will read when prepared, absolute: what an output must not be
     * (the command line refuses to write over one of them).
     */
    public List<Path> inputs() {
        return List.copyOf(inputs);
    }
}
