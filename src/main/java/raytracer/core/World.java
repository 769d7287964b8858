package raytracer.core;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import java.util.function.UnaryOperator;
import raytracer.math.BBox;
import raytracer.math.RGBColor;
import raytracer.math.Ray;

/**
 * The scene (Suffern, chapter 3): objects, lights, camera, view plane, tracer, background and
 * ambient light. Built once, then {@link #prepare}d: the object and light lists become arrays and
 * each object makes itself ready ({@link GeometricObject#prepared}: a mesh builds its BVH). Before
 * that, the render's scene analysis may leave out objects and lights that cannot change the
 * image ({@link #leaveOut}). How much of the ray tree a render traces is the render's
 * {@link RayTreeSettings}; what loading found is the loader's report.
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
    private boolean searchByTile;

    public World(ViewPlane viewPlane, Camera camera, Light ambient) {
        this.viewPlane = viewPlane;
        this.camera = camera;
        this.ambient = ambient;
    }

    public void addObject(GeometricObject object) {
        objectList.add(object);
    }

    public void addLight(Light light) {
        light.setNumber(lightList.size());
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

    /** Removes an object before {@link #prepare}: it is neither made ready nor searched. */
    public void leaveOut(GeometricObject object) {
        objectList.remove(object);
    }

    /** Removes a light before {@link #prepare}: it is never shaded with. */
    public void leaveOut(Light light) {
        lightList.remove(light);
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
        objectList.replaceAll(GeometricObject::prepared);
        List<GeometricObject> organized = organizer.apply(List.copyOf(objectList));
        objects = organized.toArray(new GeometricObject[0]);
        shadowCasters = organized.stream().filter(GeometricObject::castsShadows).toArray(GeometricObject[]::new);
        lights = lightList.toArray(new Light[0]);
        List<BBox> receivers = objectList.stream().map(GeometricObject::boundingBox).toList();
        for (Light light : lights) {
            light.prepare(receivers);
        }
    }

    /**
     * Lets shapes leave out the u, v of their hits (the inverse trigonometry of spheres and
     * cylinders), once the analysis found that no object's shading reads them.
     */
    public void leaveOutTextureCoordinates() {
        textureCoordinates = false;
    }

    /**
     * Lets camera rays search only the objects that their tile's view volume holds, once the
     * analysis found that the camera can bound it ({@link Camera#viewVolume(ViewPlane, double, double, double, double)}).
     */
    public void searchByTile() {
        searchByTile = true;
    }

    /** Whether the renderer gives each tile's camera rays the objects they can hit ({@link WorkerScratch#cameraRayObjects}). */
    public boolean searchesByTile() {
        return searchByTile;
    }

    /** Whether shapes must give their hits' u, v: true unless {@link #leaveOutTextureCoordinates} was called. */
    public boolean needsTextureCoordinates() {
        return textureCoordinates;
    }

    /**
     * Finds the closest hit along {@code ray} and completes {@code sr} for it (Suffern's
     * hit_objects, two-phase). A camera ray (depth 0) of a tile searches only the objects its
     * tile can see, when the renderer named them: the others lie wholly outside the volume that
     * holds every camera ray of the tile, so their tests could only miss.
     */
    public boolean hit(Ray ray, ShadeRec sr) {
        sr.beginSearch(ray, sr.depth, Double.POSITIVE_INFINITY);
        GeometricObject[] searched = objects;
        if (sr.depth == 0 && sr.scratch.cameraRayObjects != null) {
            searched = sr.scratch.cameraRayObjects;
            sr.scratch.skipped[Skipped.OBJECT_TESTS] += objects.length - searched.length;
        }
        for (GeometricObject object : searched) {
            object.hit(ray, sr);
        }
        if (!sr.hitAnObject()) {
            return false;
        }
        sr.complete(ray);
        return true;
    }

    /**
     * True when any shadow-casting object lies on {@code ray} with 0 &lt; t &lt; tMax. {@code ray}
     * leaves {@code sr}'s hit towards its lit side ({@link ShadeRec#spawnRay}); the object hit is
     * not tested when it {@linkplain #cannotShadow cannot shadow} such a ray, since its test could
     * only answer no (a sphere's, from its own surface, took the exact residual every time).
     */
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        sr.scratch.shadowRays++;
        GeometricObject self = cannotShadow(sr) ? sr.object : null;
        for (GeometricObject object : shadowCasters) {
            if (object != self && object.shadowHit(ray, tMax, sr)) {
                return true;
            }
        }
        return false;
    }

    /**
     * True when the object of {@code sr}'s hit cannot shadow a ray leaving it towards its lit side:
     * it says so ({@link GeometricObject#cannotShadowItself}), it was hit in world space (an
     * instance's object, placed elsewhere, could shadow its untransformed self) and, if it
     * encloses a solid, on its front face: the turned normal is then the outward one, so the ray
     * leaves the solid from outside.
     */
    private static boolean cannotShadow(ShadeRec sr) {
        GeometricObject object = sr.object;
        return object != null && !sr.isTransformed() && object.cannotShadowItself() && (!object.isClosed() || sr.frontFace);
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

    /** The lights as added (and not left out); {@link #lights} is what shading loops over after {@link #prepare}. */
    public List<Light> lightList() {
        return List.copyOf(lightList);
    }

    /** The objects as added (and not left out); after {@link #prepare}, as prepared. */
    public List<GeometricObject> objects() {
        return List.copyOf(objectList);
    }

    /** Every material the objects can be shaded with, each once, in the order of the objects. */
    public List<Material> materials() {
        Set<Material> all = new LinkedHashSet<>();
        for (GeometricObject object : objectList) {
            all.addAll(object.materials());
        }
        return List.copyOf(all);
    }

    /** What {@link #hit} searches since {@link #prepare}: the objects as the organizer grouped them. */
    public List<GeometricObject> searched() {
        return List.of(objects);
    }
}
