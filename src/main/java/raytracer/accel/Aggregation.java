package raytracer.accel;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import raytracer.core.GeometricObject;

/**
 * How the world's top-level objects are searched: a plain list, or a BVH over the bounded ones
 * (planes stay in the list). {@link Mode#AUTO} uses a list below {@link #AUTO_THRESHOLD} bounded
 * objects, where measurements show a list is faster (docs/performance.md, "List or BVH").
 */
public final class Aggregation {
    /**
     * Below this many bounded objects a list beats a BVH: ListVersusBvhBenchmark puts the crossing
     * between 16 spheres (list 117 ns, BVH 148 ns per ray) and 32 (list 232 ns, BVH 203 ns).
     */
    public static final int AUTO_THRESHOLD = 24;

    /** The choices offered to users. */
    public enum Mode {
        AUTO, LIST, MEDIAN, SAH;

        public static Mode parse(String text) {
            try {
                return valueOf(text.trim().toUpperCase(Locale.ROOT));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("unknown acceleration '" + text + "'; allowed: " + Arrays.stream(values())
                    .map(m -> m.name().toLowerCase(Locale.ROOT)).collect(Collectors.joining(", ")));
            }
        }
    }

    private Aggregation() {
    }

    /** The objects the world should search, in order: possibly one BVH plus the unbounded objects. */
    public static List<GeometricObject> organize(List<GeometricObject> objects, Mode mode) {
        List<GeometricObject> bounded = new ArrayList<>();
        List<GeometricObject> unbounded = new ArrayList<>();
        for (GeometricObject object : objects) {
            (object.boundingBox().isBounded() ? bounded : unbounded).add(object);
        }
        boolean useBvh = switch (mode) {
            case LIST -> false;
            case AUTO -> bounded.size() >= AUTO_THRESHOLD;
            case MEDIAN, SAH -> bounded.size() > 1;
        };
        if (!useBvh) {
            return objects;
        }
        List<GeometricObject> result = new ArrayList<>(unbounded);
        result.add(0, ObjectBVH.build(bounded, mode == Mode.SAH));
        return result;
    }
}
