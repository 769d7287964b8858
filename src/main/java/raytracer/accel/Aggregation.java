package raytracer.accel;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import raytracer.core.GeometricObject;
import raytracer.core.Registry;

/**
 * How the world's top-level objects are searched: a plain list, or an aggregate (a BVH) over the
 * bounded ones, planes staying in the list; the choices are the {@link Registry}'s accelerations.
 * {@code auto} uses a list below {@link #AUTO_THRESHOLD} bounded objects, where measurements show
 * a list is faster (docs/performance.md, "List or BVH").
 */
public final class Aggregation {
    /**
     * Below this many bounded objects a list beats a BVH: ListVersusBvhBenchmark puts the crossing
     * between 16 spheres (list 117 ns, BVH 148 ns per ray) and 32 (list 232 ns, BVH 203 ns).
     */
    public static final int AUTO_THRESHOLD = 24;

    /** A choice offered to users, by its registered name. */
    public record Mode(String name) {
        public static final Mode AUTO = new Mode("auto");
        public static final Mode LIST = new Mode("list");
        public static final Mode MEDIAN = new Mode("median");
        public static final Mode SAH = new Mode("sah");

        /** The registered choices, in the order they were registered. */
        public static Mode[] values() {
            return Registry.standard().accelerations().names().stream().map(Mode::new).toArray(Mode[]::new);
        }

        /** The choice of that name, read as {@code --accel} takes it (case and surrounding blanks ignored). */
        public static Mode parse(String text) {
            String name = text.trim().toLowerCase(Locale.ROOT);
            if (Registry.standard().accelerations().find(name).isEmpty()) {
                throw new IllegalArgumentException("unknown acceleration '" + text + "'; allowed: "
                                                   + String.join(", ", Registry.standard().accelerations().names()));
            }
            return new Mode(name);
        }
    }

    private Aggregation() {
    }

    /** The objects the world should search, in order: possibly one aggregate plus the unbounded objects. */
    public static List<GeometricObject> organize(List<GeometricObject> objects, Mode mode) {
        List<GeometricObject> bounded = new ArrayList<>();
        List<GeometricObject> unbounded = new ArrayList<>();
        for (GeometricObject object : objects) {
            (object.boundingBox().isBounded() ? bounded : unbounded).add(object);
        }
        GeometricObject aggregate = bounded.isEmpty() ? null : Registry.standard().accelerations().find(mode.name())
            .orElseThrow(() -> new IllegalArgumentException("unknown acceleration '" + mode.name() + "'"))
            .make().apply(bounded);
        if (aggregate == null) {
            return objects;
        }
        List<GeometricObject> result = new ArrayList<>(unbounded);
        result.add(0, aggregate);
        return result;
    }
}
