package raytracer.render;

import java.util.List;
import raytracer.accel.MedianSplitBuilder;
import raytracer.accel.MeshBVH;
import raytracer.accel.SahBuilder;
import raytracer.cameras.Pinhole;
import raytracer.cameras.ThinLens;
import raytracer.core.Camera;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.Sampler;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.io.obj.ObjException;
import raytracer.io.obj.ObjLoader;
import raytracer.io.obj.TestAssets;
import raytracer.lights.Ambient;
import raytracer.lights.AreaLight;
import raytracer.lights.Directional;
import raytracer.lights.PointLight;
import raytracer.materials.Dielectric;
import raytracer.materials.Matte;
import raytracer.materials.Phong;
import raytracer.math.Matrix4;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.samplers.MultiJittered;
import raytracer.shapes.Box;
import raytracer.shapes.Instance;
import raytracer.shapes.Plane;
import raytracer.shapes.Rectangle;
import raytracer.shapes.Sphere;
import raytracer.shapes.mesh.Mesh;
import raytracer.textures.Checker;
import raytracer.tracers.AreaLighting;
import raytracer.tracers.Whitted;

/**
 * The scenes of {@link NumericalStressTest}, each built at any scale s and moved by any offset d
 * (added to x, y and z): every length is multiplied by s, so each image is the same in exact
 * arithmetic. What carries a unit scales with it too: point-light intensity by s^2 (radiance
 * I / r^2), absorption by 1 / s (Beer's exponent sigma_a t), the lens radius and the focal distance
 * by s. Area-light radiance, angles, colours and the cutoff carry none.
 */
final class StressScenes {
    static final int W = 64;
    static final int H = 48;

    private StressScenes() {
    }

    /** A scene of the suite: builds its world at scale s, moved by offset d. */
    interface Scene {
        World build(double s, double d);
    }

    /** The closed bunny mesh, its vertices themselves scaled and moved, shadowing itself and the floor. */
    static World bunny(double s, double d) {
        World world = world(1, CenterSampler.INSTANCE, 2, pinhole(s, d));
        add(world, floor(s, d), matte(0.8, 0.75, 0.7));
        add(world, bakedBunny(s, d, false, 0), new Phong(0.2, 0.7, new RGBColor(0.9, 0.85, 0.8),
                                                                              0.3, RGBColor.WHITE, 30, false));
        world.addLight(new PointLight(40 * s * s, RGBColor.WHITE, p(s, d, -3, 5, 4)));
        return prepared(world);
    }

    /**
     * Absorbing glass: a glass bunny (SAH tree) and a glass sphere over a checker floor, to depth 8:
     * refraction in and out of a mesh, total internal reflection and Beer's law over scaled lengths.
     */
    static World glass(double s, double d) {
        World world = world(1, CenterSampler.INSTANCE, 8, pinhole(s, d));
        add(world, floor(s, d), checker(s));
        add(world, bakedBunny(s, d, true, -0.5), new Dielectric(1.5, new RGBColor(0.9 / s, 0.1 / s, 0.6 / s), 0.5, 200));
        add(world, new Sphere(p(s, d, 1.1, 0.5, 0.4), 0.5 * s), new Dielectric(1.5, new RGBColor(0.2 / s, 0.6 / s, 1.2 / s), 0.5, 200));
        world.addLight(new PointLight(40 * s * s, RGBColor.WHITE, p(s, d, -3, 5, 4)));
        return prepared(world);
    }

    /**
     * Soft shadows of a sphere and a turned box under a rectangular area light, 4 pixel samples and 4
     * light samples each: the sample pattern is a function of the pixel and the seed alone, so the
     * shadow rays go to the same (scaled) points of the light at every scale.
     */
    static World areaLight(double s, double d) {
        World world = world(4, new MultiJittered(), 1, pinhole(s, d));
        Matte matte = matte(0.8, 0.8, 0.8);
        add(world, floor(s, d), matte);
        add(world, new Sphere(p(s, d, -0.6, 0.5, 0), 0.5 * s), matte);
        add(world, turnedBox(s, d), matte);
        world.addLight(AreaLight.rectangle(p(s, d, -1, 2.5, -0.5), new Vector3D(1.5 * s, 0, 0), new Vector3D(0, 0, 1.2 * s),
                                           6, RGBColor.WHITE, 4));
        world.setTracer(AreaLighting::new); // area lights are sampled (Suffern, chapter 18)
        return prepared(world);
    }

    /** The thin lens focused on the middle of three spheres set at different depths. */
    static World thinLens(double s, double d) {
        Point3D eye = p(s, d, 0, 1.0, 3.2);
        Point3D focus = p(s, d, 0, 0.5, 0);
        double focal = Math.hypot(0.5, 3.2) * s;
        ThinLens camera = new ThinLens(eye, focus, Vector3D.UP, 45, 0.2 * s, focal);
        World world = world(4, new MultiJittered(), 1, camera);
        add(world, floor(s, d), checker(s));
        add(world, new Sphere(p(s, d, -1.2, 0.5, -2), 0.5 * s), matte(0.9, 0.3, 0.2));
        add(world, new Sphere(focus, 0.5 * s), matte(0.3, 0.9, 0.3));
        add(world, new Sphere(p(s, d, 0.7, 0.3, 1.5), 0.3 * s), matte(0.2, 0.4, 0.9));
        world.addLight(new PointLight(40 * s * s, RGBColor.WHITE, p(s, d, -3, 5, 4)));
        return prepared(world);
    }

    /**
     * The bunny left in its own coordinates (about 0.15 units tall) under an instance that scales,
     * turns about two axes and moves it, beside a turned instanced box: the ray goes into object
     * space and the hit, with its error bounds, comes back.
     */
    static World instanced(double s, double d) {
        World world = world(1, CenterSampler.INSTANCE, 2, pinhole(s, d));
        add(world, floor(s, d), matte(0.8, 0.75, 0.7));
        MeshBVH mesh = bvh(Bunny.MESH, false);
        Matrix4 toWorld = Matrix4.translate(d - 0.3 * s, d + 0.25 * s, d)
            .multiply(Matrix4.scale(10 * s, 10 * s, 10 * s))
            .multiply(Matrix4.rotateY(140))
            .multiply(Matrix4.rotateZ(-25))
            .multiply(Matrix4.translate(0.017, -0.11, 0));
        add(world, new Instance(mesh, toWorld), matte(0.9, 0.8, 0.6));
        add(world, turnedBox(s, d), matte(0.5, 0.6, 0.9));
        world.addLight(new PointLight(40 * s * s, RGBColor.WHITE, p(s, d, -3, 5, 4)));
        return prepared(world);
    }

    /**
     * Flat surfaces that lie in coordinate planes, where a hit's error bound along the normal is 0
     * (shadow acne on a floor mesh at y = 0): a floor quad at y = 0 (at offset 0), a back
     * wall at z = -2, a box of twelve triangles resting on the floor and a thin plate of quads
     * standing on it, under a point light and a directional one. With {@code meshes} false the
     * same surfaces are analytic (rectangles, a box), the reference the meshes must match.
     */
    static World flat(double s, double d, boolean meshes) {
        World world = world(1, CenterSampler.INSTANCE, 2, pinhole(s, d));
        Matte floor = matte(0.8, 0.75, 0.7);
        add(world, quad(meshes, p(s, d, -4, 0, -4), p(s, d, -4, 0, 4), p(s, d, 4, 0, 4), p(s, d, 4, 0, -4)), floor);
        add(world, quad(meshes, p(s, d, -4, 0, -2), p(s, d, 4, 0, -2), p(s, d, 4, 3, -2), p(s, d, -4, 3, -2)), matte(0.6, 0.7, 0.8));
        add(world, box(meshes, p(s, d, -1.4, 0, -0.6), p(s, d, -0.4, 1, 0.4)), matte(0.9, 0.4, 0.3));
        add(world, box(meshes, p(s, d, 0.6, 0, -0.1), p(s, d, 1.4, 0.9, 0.1)), matte(0.3, 0.8, 0.4));
        addLights(world, s, d);
        return prepared(world);
    }

    /**
     * A floor tilted through the scene's origin (normal (0.2, 1, 0.1)), a mesh of two triangles or
     * a rectangle with the same corners, a box of quads standing on it and lit as {@link #flat}.
     */
    static World tiltedFloor(double s, double d, boolean meshes) {
        World world = world(1, CenterSampler.INSTANCE, 2, pinhole(s, d));
        Vector3D n = new Vector3D(0.2, 1, 0.1).normalize();
        Vector3D a = n.cross(new Vector3D(0, 0, 1)).normalize();
        Vector3D b = a.cross(n);
        Point3D o = p(s, d, 0, 0, 0);
        Vector3D ea = a.scale(4 * s);
        Vector3D eb = b.scale(4 * s);
        add(world, quad(meshes, o.add(ea.scale(-1)).add(eb.scale(-1)), o.add(ea).add(eb.scale(-1)), o.add(ea).add(eb),
                        o.add(ea.scale(-1)).add(eb)), matte(0.8, 0.75, 0.7));
        add(world, box(meshes, p(s, d, -0.5, 0.6, -0.5), p(s, d, 0.3, 1.2, 0.3)), matte(0.9, 0.4, 0.3));
        addLights(world, s, d);
        return prepared(world);
    }

    private static void addLights(World world, double s, double d) {
        world.addLight(new PointLight(40 * s * s, RGBColor.WHITE, p(s, d, 3, 2.5, 2)));
        world.addLight(new Directional(1.2, new RGBColor(0.8, 0.85, 1), new Vector3D(-2, 3, 1)));
    }

    /** The quad a, b, c, d: two triangles of a mesh, or a rectangle at a with edges b - a and d - a. */
    private static GeometricObject quad(boolean mesh, Point3D a, Point3D b, Point3D c, Point3D dd) {
        if (!mesh) {
            return new Rectangle(a, b.sub(a), dd.sub(a));
        }
        double[] positions = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), dd.x(), dd.y(), dd.z()};
        return bvh(new Mesh(positions, null, null, new int[] {0, 1, 2, 0, 2, 3}, null), false);
    }

    /** The box between two corners: twelve triangles, or a Box. */
    private static GeometricObject box(boolean mesh, Point3D lo, Point3D hi) {
        if (!mesh) {
            return new Box(lo, hi);
        }
        double[] x = {lo.x(), hi.x()};
        double[] y = {lo.y(), hi.y()};
        double[] z = {lo.z(), hi.z()};
        double[] positions = new double[24];
        for (int i = 0; i < 8; i++) {
            positions[3 * i] = x[i & 1];
            positions[3 * i + 1] = y[(i >> 1) & 1];
            positions[3 * i + 2] = z[(i >> 2) & 1];
        }
        int[] faces = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
        return bvh(new Mesh(positions, null, null, faces, null), false);
    }

    private static World world(int samples, Sampler sampler, int depth, Camera camera) {
        World world = new World(new ViewPlane(W, H, samples, sampler, depth, 1), camera, new Ambient(0.05, RGBColor.WHITE));
        world.setBackground(new RGBColor(0.1, 0.12, 0.2));
        world.setTracer(Whitted::new);
        return world;
    }

    private static Pinhole pinhole(double s, double d) {
        return new Pinhole(p(s, d, 0, 1.0, 3.2), p(s, d, 0, 0.6, 0), Vector3D.UP, 45);
    }

    /** The point d + s (x, y, z). */
    static Point3D p(double s, double d, double x, double y, double z) {
        return new Point3D(d + s * x, d + s * y, d + s * z);
    }

    private static Plane floor(double s, double d) {
        return new Plane(p(s, d, 0, 0, 0), new Normal(0, 1, 0));
    }

    private static Instance turnedBox(double s, double d) {
        Box box = new Box(new Point3D(-0.35 * s, 0, -0.35 * s), new Point3D(0.35 * s, 0.8 * s, 0.35 * s));
        return new Instance(box, Matrix4.translate(d + 0.9 * s, d, d - 0.2 * s).multiply(Matrix4.rotateY(35)));
    }

    private static Matte matte(double r, double g, double b) {
        return new Matte(0.2, 0.8, new RGBColor(r, g, b));
    }

    private static Matte checker(double s) {
        Matte m = matte(1, 1, 1);
        m.setTexture(new Checker(new RGBColor(0.85, 0.85, 0.8), new RGBColor(0.25, 0.3, 0.35), 0.5 * s));
        return m;
    }

    /**
     * The bunny, its base on the floor, 1.54 units tall, centred at x = shift, with every vertex at
     * d + s p: the mesh itself holds the large or small coordinates.
     */
    private static MeshBVH bakedBunny(double s, double d, boolean sah, double shift) {
        Mesh m = Bunny.MESH;
        double[] p = m.positions().clone();
        for (int i = 0; i < p.length; i += 3) {
            p[i] = d + s * (10 * (p[i] + 0.017) + shift);
            p[i + 1] = d + s * 10 * (p[i + 1] - 0.0329874);
            p[i + 2] = d + s * 10 * p[i + 2];
        }
        return bvh(new Mesh(p, null, null, m.triangles(), null), sah);
    }

    private static MeshBVH bvh(Mesh mesh, boolean sah) {
        return new MeshBVH(mesh, sah ? new SahBuilder(4).build(MeshBVH.triangleBounds(mesh))
                                     : new MedianSplitBuilder(8).build(MeshBVH.triangleBoxes(mesh)), List.<Material>of());
    }

    /** The bunny in its own coordinates (69,451 triangles, about 0.15 units tall), loaded once. */
    private static final class Bunny {
        static final Mesh MESH = load();

        private static Mesh load() {
            try {
                return ObjLoader.load(TestAssets.path("meshes/stanford-bunny.obj.gz"), false).mesh();
            } catch (ObjException e) {
                throw new IllegalStateException(e.getMessage(), e);
            }
        }
    }

    private static World prepared(World world) {
        world.prepare();
        return world;
    }

    private static void add(World world, GeometricObject object, Material material) {
        object.setMaterial(material);
        world.addObject(object);
    }
}
