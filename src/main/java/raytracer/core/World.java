package raytracer.core;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import raytracer.math.RGBColor;
import raytracer.math.Ray;

/**
 * The scene (Suffern, chapter 3): objects, lights, camera, view plane and tracer. Built once, then
 * {@link #prepare}d: the object and light lists become arrays and the scene is looked at once to
 * leave out work it cannot use.
 */
public final class World {
    private ViewPlane viewPlane;
    private Camera camera;
    private Tracer tracer;
    private Background background = (ray, out) -> out.setBlack();
    private Light ambient;
    private ShadingPass pass = ShadingPass.FULL;
    private double cutoff;
    private boolean linearDisplay;
    private final List<GeometricObject> objectList = new ArrayList<>();
    private final List<Light> lightList = new ArrayList<>();

    private GeometricObject[] objects = new GeometricObject[0];
    private GeometricObject[] shadowCasters = new GeometricObject[0];
    private Light[] lights = new Light[0];
    private final Map<String, Long> timings = new LinkedHashMap<>();
    private final List<String> warnings = new ArrayList<>();
    private final List<String> statistics = new ArrayList<>();

    public World(ViewPlane viewPlane, Camera camera, Light ambient) {
        this.viewPlane = viewPlane;
        this.camera = camera;
        this.ambient = ambient;
    }

    public void addObject(GeometricObject object) {
        objectList.add(object);
    }

    public void addLight(Light light) {
        lightList.add(light);
    }

    public void setTracer(Function<World, Tracer> factory) {
        this.tracer = factory.apply(this);
    }

    public void setBackground(RGBColor color) {
        this.background = (ray, out) -> out.set(color);
    }

    public void setBackground(Background background) {
        this.background = background;
    }

    public void setViewPlane(ViewPlane viewPlane) {
        this.viewPlane = viewPlane;
    }

    public void setCamera(Camera camera) {
        this.camera = camera;
    }

    /** Freezes the lists into arrays, searching the objects as a plain list. */
    public void prepare() {
        prepare(UnaryOperator.identity());
    }

    /**
     * Freezes the lists into arrays; call after the last change and before rendering.
     * {@code organizer} may regroup the objects (e.g. under a BVH) for faster searching.
     */
    public void prepare(UnaryOperator<List<GeometricObject>> organizer) {
        List<GeometricObject> organized = organizer.apply(List.copyOf(objectList));
        objects = organized.toArray(new GeometricObject[0]);
        shadowCasters = organized.stream().filter(GeometricObject::castsShadows).toArray(GeometricObject[]::new);
        lights = lightList.toArray(new Light[0]);
    }

    /**
     * Finds the closest hit along {@code ray} and completes {@code sr} for it (Suffern's
     * hit_objects, two-phase).
     */
    public boolean hit(Ray ray, ShadeRec sr) {
        sr.beginSearch(ray, sr.depth, Double.POSITIVE_INFINITY);
        for (GeometricObject object : objects) {
            object.hit(ray, sr);
        }
        if (!sr.hitAnObject()) {
            return false;
        }
        sr.complete(ray);
        return true;
    }

    /** True when any shadow-casting object lies on {@code ray} with 0 &lt; t &lt; tMax. */
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        sr.scratch.shadowRays++;
        for (GeometricObject object : shadowCasters) {
            if (object.shadowHit(ray, tMax, sr)) {
                return true;
            }
        }
        return false;
    }

    /** Notes how long a step of building this world took (parsing a mesh, building its BVH). */
    public void recordTiming(String step, long nanos) {
        timings.merge(step, nanos, Long::sum);
    }

    /** Build steps and their durations in nanoseconds, in the order they were first recorded. */
    public Map<String, Long> timings() {
        return java.util.Collections.unmodifiableMap(timings);
    }

    /** Notes a figure of what was built (a mesh's triangles and vertices), one line, for --stats. */
    public void addStatistic(String line) {
        statistics.add(line);
    }

    public List<String> statistics() {
        return List.copyOf(statistics);
    }

    /** Notes something odd but harmless found while building (a missing texture); the CLI prints these. */
    public void addWarning(String warning) {
        warnings.add(warning);
    }

    public List<String> warnings() {
        return List.copyOf(warnings);
    }

    public void setPass(ShadingPass pass) {
        this.pass = pass;
    }

    /** Which terms the first hit shows (report figures 4 and 6); FULL normally. */
    public ShadingPass pass() {
        return pass;
    }

    /**
     * The adaptive ray-tree cutoff (Hall and Greenberg 1983): branches whose path weight is below it
     * in every channel are not traced, light samples that would add less than it (in display units)
     * are not shadow-tested, and hits below the camera's take area-light samples in proportion to
     * their weight. 0, the default, traces the whole tree to the max depth.
     */
    public void setCutoff(double cutoff) {
        if (!(cutoff >= 0 && cutoff < 1)) {
            throw new IllegalArgumentException("cutoff must be in [0, 1), got " + cutoff);
        }
        this.cutoff = cutoff;
    }

    public double cutoff() {
        return cutoff;
    }

    /**
     * Whether PNG output skips the sRGB transfer curve and writes clamped radiance as code values,
     * as the report's renderer did (its darker, more contrasted images); false by default.
     */
    public void setLinearDisplay(boolean linearDisplay) {
        this.linearDisplay = linearDisplay;
    }

    public boolean linearDisplay() {
        return linearDisplay;
    }

    public ViewPlane viewPlane() {
        return viewPlane;
    }

    public Camera camera() {
        return camera;
    }

    public Tracer tracer() {
        return tracer;
    }

    public Background background() {
        return background;
    }

    public Light ambient() {
        return ambient;
    }

    public Light[] lights() {
        return lights;
    }

    public List<GeometricObject> objects() {
        return List.copyOf(objectList);
    }

    /** What {@link #hit} searches since {@link #prepare}: the objects as the organizer grouped them. */
    public List<GeometricObject> searched() {
        return List.of(objects);
    }
}
