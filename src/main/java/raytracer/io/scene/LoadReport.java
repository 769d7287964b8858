package raytracer.io.scene;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What loading a scene found besides the scene itself: how long its steps took (parsing a mesh,
 * building its BVH), figures of what was built (a mesh's triangles and vertices) and warnings
 * (something odd but harmless, such as a missing texture). Filled by the readers while loading,
 * read by the command line after it.
 */
public final class LoadReport {
    private final Map<String, Long> timings = new LinkedHashMap<>();
    private final List<String> statistics = new ArrayList<>();
    private final List<String> warnings = new ArrayList<>();

    /** Notes how long a step took; a step recorded twice adds up. */
    void recordTiming(String step, long nanos) {
        timings.merge(step, nanos, Long::sum);
    }

    void addStatistic(String line) {
        statistics.add(line);
    }

    void addWarning(String warning) {
        warnings.add(warning);
    }

    /** Steps and their durations in nanoseconds, in the order they were first recorded. */
    public Map<String, Long> timings() {
        return Collections.unmodifiableMap(timings);
    }

    /** One line per figure, for --stats. */
    public List<String> statistics() {
        return List.copyOf(statistics);
    }

    public List<String> warnings() {
        return List.copyOf(warnings);
    }
}
