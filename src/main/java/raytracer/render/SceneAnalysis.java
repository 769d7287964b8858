package raytracer.render;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import raytracer.core.Camera;
import raytracer.core.GeometricObject;
import raytracer.core.Light;
import raytracer.core.Material;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadingPass;
import raytracer.core.Skip;
import raytracer.core.Skipped;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;

/**
 * Decides, once the scene is loaded and the command line has changed it, what work its render can
 * leave out without changing one bit of the image, and leaves it out before {@link World#prepare}:
 * lights that emit nothing or lie behind an opaque plane, terms of materials that are zero at
 * every hit, recursion no material uses, objects no ray can reach (a mesh so left out is never
 * built), shadow rays no object can block, texture coordinates no texture reads; and it lets each
 * tile's camera rays search only what the tile can see. Every decision is a proof, not a guess:
 * where the proof needs something the objects cannot tell, nothing is left out. It asks the objects what they need, never their classes.
 * {@link #skips} lists each decision with its reason; the counts of what it saved are the
 * render's ({@link RenderStats#skipped}).
 */
public final class SceneAnalysis {
    private final World world;
    private final ShadingPass pass;
    /** The lights in the scene file's order, which numbers them in messages. */
    private final List<Light> lights;
    private final List<Skip> skips = new ArrayList<>();

    private SceneAnalysis(World world, RayTreeSettings rayTree) {
        this.world = world;
        this.pass = rayTree.pass();
        this.lights = world.lightList();
    }

    /** Analyses {@code world} (not yet prepared) for a render with {@code rayTree}, and leaves out what it can. */
    public static SceneAnalysis apply(World world, RayTreeSettings rayTree) {
        SceneAnalysis analysis = new SceneAnalysis(world, rayTree);
        analysis.lightsThatEmitNothing();
        analysis.lightsBehindAPlane();
        analysis.zeroTerms();
        analysis.recursion();
        analysis.unreachableObjects();
        analysis.shadowRays();
        analysis.textureCoordinates();
        analysis.searchByTile();
        return analysis;
    }

    /** What was left out and why, in the order decided. */
    public List<Skip> skips() {
        return List.copyOf(skips);
    }

    /**
     * A light that emits nothing adds f 0 = +0 wherever it is shaded: one that draws no samples is
     * left out; one that does (an area light) keeps its draws, so that the others' samples do not
     * move, but traces no shadow rays.
     */
    private void lightsThatEmitNothing() {
        for (Light light : lights) {
            if (!light.isBlack()) {
                continue;
            }
            if (!light.drawsSamples()) {
                world.leaveOut(light);
                skips.add(new Skip(Skipped.UNCOUNTED, name(light) + " left out", "it emits nothing"));
            } else if (light.castsShadows()) {
                light.leaveOutShadowRays();
                skips.add(new Skip(Skipped.SHADOW_RAYS, "no shadow rays towards " + name(light), "it emits nothing"));
            }
        }
    }

    /**
     * A light wholly beyond an opaque plane that casts shadows, with the camera's rays and every
     * other object strictly on the near side, lights nothing that can be seen: no ray crosses the
     * plane (it is whole, and its material lets none through), so every hit is on the near side;
     * a shadow ray from a hit on another object crosses the plane before it reaches the light, and
     * a hit on the plane itself has its normal turned to the ray, to the near side, away from the
     * light. Each of its samples would add nothing, so it is left out. An object touching the
     * plane keeps the light: its points within rounding of the plane could be lit from beyond. So
     * does a light within rounding of the plane at the scene's scale, where a shadow ray's length
     * and the plane's distance along it come out alike: the light's margin is taken relative to
     * the largest coordinate of the camera's origins and the other objects. A light that draws
     * samples (an area light) is kept too, as one that emits nothing is.
     */
    private void lightsBehindAPlane() {
        BBox origins = world.camera().rayOrigins(world.viewPlane());
        if (origins == null) {
            return;
        }
        List<GeometricObject> objects = world.objects();
        double size = origins.maxAbs();
        for (GeometricObject object : objects) {
            BBox box = object.boundingBox();
            if (box.isBounded()) {
                size = Math.max(size, box.maxAbs());
            }
        }
        for (GeometricObject wall : objects) {
            HalfSpace side = wall.wholePlane();
            if (side == null || !wall.castsShadows() || wall.materials().stream().anyMatch(m -> m.needs().refraction())) {
                continue;
            }
            for (HalfSpace near : List.of(side, side.flipped())) {
                HalfSpace far = near.flipped();
                if (!far.excludes(origins) || !objects.stream().allMatch(o -> o == wall || far.excludes(o.boundingBox()))) {
                    continue;
                }
                for (Light light : world.lightList()) {
                    if (light.castsShadows() && !light.drawsSamples() && light.liesBeyond(near.atScale(size))) {
                        world.leaveOut(light);
                        skips.add(new Skip(Skipped.UNCOUNTED, name(light) + " left out",
                                           "it lies behind the " + wall.description() + ", and the camera and every other object in front"));
                    }
                }
            }
        }
    }

    /** "light 2 (point light)": numbered as in the scene file. */
    private String name(Light light) {
        return "light " + (lights.indexOf(light) + 1) + " (" + light.description() + ")";
    }

    /**
     * Each material leaves out the terms that are zero at every hit. A ray of weight zero may be
     * left out only if nothing in the scene draws random numbers, which that ray's subtree could
     * have drawn (every later draw of the pixel would move).
     */
    private void zeroTerms() {
        boolean mayDropRays = !drawsSamples();
        for (Material material : world.materials()) {
            skips.addAll(material.simplify(world, mayDropRays));
        }
    }

    private boolean drawsSamples() {
        return world.lightList().stream().anyMatch(Light::drawsSamples)
               || world.materials().stream().anyMatch(m -> m.needs().drawsSamples());
    }

    /**
     * Max depth 0 when no secondary ray can be traced or bring light back: no material traces
     * any; or the pass shows neither reflection nor refraction at the first hit, so none is
     * started; or the tracer returns black for them and no material draws random numbers before
     * tracing them. Then neither the per-depth records nor the rays are made.
     */
    private void recursion() {
        ViewPlane vp = world.viewPlane();
        if (vp.maxDepth() == 0) {
            return;
        }
        String why = null;
        if (world.materials().stream().noneMatch(m -> m.needs().rays())) {
            why = "no material traces secondary rays";
        } else if (!pass.reflection(0) && !pass.refraction(0)) {
            why = "the pass '" + pass.key() + "' traces no ray from the first hit";
        } else if (!world.tracer().tracesSecondaryRays() && world.materials().stream().noneMatch(m -> m.needs().drawsSamples())) {
            why = "the tracer returns black for secondary rays";
        }
        if (why != null) {
            world.setViewPlane(vp.withMaxDepth(0));
            skips.add(new Skip(Skipped.UNCOUNTED, "max depth " + vp.maxDepth() + " -> 0 (no recursion)", why));
        }
    }

    /**
     * With no secondary rays, an object is reached only by camera rays and by shadow rays from
     * what they hit. One wholly outside a face of the camera's view volume is reached by neither
     * when it casts no shadows, or when every light it could shadow lies on the inner side of that
     * face: a shadow ray from a point inside towards a light inside stays inside. It is left out,
     * so a mesh is neither built nor traced.
     */
    private void unreachableObjects() {
        if (world.viewPlane().maxDepth() > 0 && world.tracer().tracesSecondaryRays()) {
            return;
        }
        Camera camera = world.camera();
        List<HalfSpace> volume = camera.viewVolume(world.viewPlane());
        for (GeometricObject object : world.objects()) {
            BBox box = object.boundingBox();
            for (HalfSpace face : volume) {
                if (face.excludes(box) && (!object.castsShadows() || shadowsStayWithin(face))) {
                    world.leaveOut(object);
                    skips.add(new Skip(Skipped.UNCOUNTED, object.description() + " left out (not built, not traced)",
                                       "outside the view, casting no shadow into it, and no secondary rays"));
                    break;
                }
            }
        }
    }

    /**
     * True when no shadow ray from inside {@code h} leaves it: asked of every light, and of the
     * ambient light, which casts shadows when it traces rays of its own (ambient occlusion,
     * docs/teaching.md exercise 4) and then cannot say where they go.
     */
    private boolean shadowsStayWithin(HalfSpace h) {
        return Stream.concat(world.lightList().stream(), Stream.of(world.ambient()))
            .allMatch(light -> !light.castsShadows() || light.keepsShadowRaysWithin(h));
    }

    /**
     * A light needs no shadow rays when no object casts shadows, or when no shadow caster can come
     * between it and a point that can be shaded: a caster that cannot shadow itself (and, if it
     * encloses a solid, is never seen from inside: the camera is outside it and nothing refracts)
     * and is cut off by an axis-aligned plane from every other object and from the light.
     */
    private void shadowRays() {
        List<GeometricObject> objects = world.objects();
        List<GeometricObject> casters = objects.stream().filter(GeometricObject::castsShadows).toList();
        for (Light light : world.lightList()) {
            if (!light.castsShadows()) {
                continue;
            }
            String why = casters.isEmpty() ? "no object casts shadows"
                : casters.stream().allMatch(c -> cannotOcclude(c, light, objects))
                ? "no object can come between it and a point it lights" : null;
            if (why != null) {
                light.leaveOutShadowRays();
                skips.add(new Skip(Skipped.SHADOW_RAYS, "no shadow rays towards " + name(light), why));
            }
        }
    }

    private boolean cannotOcclude(GeometricObject caster, Light light, List<GeometricObject> objects) {
        if (!caster.cannotShadowItself() || caster.isClosed() && mayBeSeenFromInside(caster)) {
            return false;
        }
        BBox box = caster.boundingBox();
        for (GeometricObject other : objects) {
            if (other != caster && !BoxSides.separated(box, other.boundingBox(), light)) {
                return false;
            }
        }
        return true;
    }

    /**
     * No hit needs its u, v when no object left in the scene has a texture that reads them (an
     * object without a material of its own, such as a mesh with per-face materials, may).
     */
    private void textureCoordinates() {
        if (world.objects().stream().noneMatch(GeometricObject::usesTextureCoordinates)) {
            world.leaveOutTextureCoordinates();
            skips.add(new Skip(Skipped.TEXTURE_COORDINATES, "u, v of hits not computed", "no texture reads them"));
        }
    }

    /**
     * Camera rays search only the objects, and the parts of a BVH, that their tile can see, when
     * the camera can bound the rays of a part of its image and some object is bounded (an
     * unbounded one, a plane, is in every tile's view). The tiles' lists are the renderer's
     * ({@link TileObjects}); the parts of a BVH left out show as fewer box tests per ray.
     */
    private void searchByTile() {
        Camera camera = world.camera();
        if (camera.viewVolume(world.viewPlane()).isEmpty() || world.objects().stream().noneMatch(o -> o.boundingBox().isBounded())) {
            return;
        }
        world.searchByTile();
        skips.add(new Skip(Skipped.OBJECT_TESTS, "camera rays test only the objects, and the parts of a BVH, that their tile can see",
                           "what lies wholly outside the view volume of a tile's camera rays cannot be hit by them"));
    }

    /** True unless the camera's rays start outside the object's box and no material refracts. */
    private boolean mayBeSeenFromInside(GeometricObject object) {
        BBox origins = world.camera().rayOrigins(world.viewPlane());
        if (origins == null || world.materials().stream().anyMatch(m -> m.needs().refraction())) {
            return true;
        }
        return !BoxSides.separated(object.boundingBox(), origins);
    }
}
