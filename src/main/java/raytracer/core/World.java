package raytracer.core;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import raytracer.math.RGBColor;
import raytracer.math.Ray;

/**
 * The scene (Suffern, chapter 3): objects, lights, camera, view plane, tracer, background and
 * ambient light. Built once, then {@link #prepare}d: the object and light lists become arrays and
 * the scene is looked at once to leave out work it cannot use. How much of the ray tree a render
 * traces is the render's {@link RayTreeSettings}; what loading found is the loader's report.
 */
public final class World {
    private ViewPlane viewPlane;
    private Camera camera;
    private Tracer tracer;
    private Background background = (ray, out) -> out.setBlack();
    private Light ambient;
    private final List<GeometricObject> objectList = new ArrayList<>();
    private final List<Light> lightList = new ArrayList<>();

    private GeometricObject[] objects = new GeometricObject[0];
    private GeometricObject[] shadowCasters = new GeometricObject[0];
    private Light[] lights = new Light[0];
    private boolean textureCoordinates = true;

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
        textureCoordinates = objectList.stream().anyMatch(GeometricObject::usesTextureCoordinates);
    }

    /**
     * False once {@link #prepare} found that no object's shading reads u, v (no textures): shapes
     * then leave out the inverse trigonometry that computes them (a quarter of a simple scene's
     * sample). True before.
     */
    public boolean needsTextureCoordinates() {
        return textureCoordinates;
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
