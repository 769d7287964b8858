package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.cameras.Pinhole;
import raytracer.cameras.ThinLens;
import raytracer.core.Camera;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.math.HalfSpace;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;
import raytracer.shapes.Instance;
import raytracer.shapes.Sphere;
import raytracer.shapes.mesh.Mesh;

/**
 * A BVH searched from the subtree that a tile's view volume leaves ({@link FlatBVH#startFor})
 * finds what it finds from the root, to the bit: the same t, triangle or object, for camera rays
 * through the corners and random points of small windows of random cameras, on a mesh of 20,480
 * triangles and on a tree of 300 spheres, at scales 1e-2 to 1e4. It tests fewer boxes, and the
 * searches do start below the root.
 */
class SubtreeSearchTest {
    private static final ViewPlane VP = new ViewPlane(640, 480, 1, (n, rng, xs, ys) -> { }, 0, 1);

    @Test
    void aMeshSearchedFromItsTilesSubtreeFindsTheSameHits() {
        SplittableRandom random = new SplittableRandom(31);
        int startedLower = 0;
        for (int c = 0; c < 16; c++) {
            double scale = Math.pow(10, random.nextDouble(-2, 4));
            Mesh unit = Icosphere.make(5);
            double[] p = unit.positions().clone();
            for (int i = 0; i < p.length; i++) {
                p[i] *= scale;
            }
            Mesh mesh = new Mesh(p, null, null, unit.triangles(), null);
            MeshBVH bvh = new MeshBVH(mesh, new MedianSplitBuilder(4).build(MeshBVH.triangleBoxes(mesh)), List.of());
            startedLower += compare(bvh, camera(random, c, scale), random, scale);
        }
        assertTrue(startedLower > 100, "few searches started below the root: " + startedLower);
    }

    /**
     * A mesh under a transform (rotation, uneven scale, translation), searched from its subtree in
     * its own space: the tile's faces carried there, with a margin grown by the matrix's condition.
     */
    @Test
    void anInstancedMeshSearchedFromItsTilesSubtreeFindsTheSameHits() {
        SplittableRandom random = new SplittableRandom(33);
        Mesh unit = Icosphere.make(5);
        MeshBVH bvh = new MeshBVH(unit, new MedianSplitBuilder(4).build(MeshBVH.triangleBoxes(unit)), List.of());
        int startedLower = 0;
        for (int c = 0; c < 16; c++) {
            double scale = Math.pow(10, random.nextDouble(-2, 4));
            Matrix4 place = Matrix4.translate(random.nextDouble(-0.3, 0.3) * scale, random.nextDouble(-0.3, 0.3) * scale, 0)
                .multiply(Matrix4.rotateY(random.nextDouble(360))).multiply(Matrix4.rotateX(random.nextDouble(360)))
                .multiply(Matrix4.scale(scale * random.nextDouble(0.2, 1), scale * random.nextDouble(0.2, 1), scale * random.nextDouble(0.2, 1)));
            startedLower += compare(new Instance(bvh, place), camera(random, c, scale), random, scale);
        }
        // the placed sphere covers less of the image than the others: fewer windows see it
        assertTrue(startedLower > 30, "few searches started below the root: " + startedLower);
    }

    @Test
    void aTreeOfSpheresSearchedFromItsTilesSubtreeFindsTheSameHits() {
        SplittableRandom random = new SplittableRandom(32);
        int startedLower = 0;
        for (int c = 0; c < 16; c++) {
            double scale = Math.pow(10, random.nextDouble(-2, 4));
            List<GeometricObject> spheres = new ArrayList<>();
            for (int k = 0; k < 300; k++) {
                spheres.add(new Sphere(new Point3D(random.nextDouble(-1, 1) * scale, random.nextDouble(-1, 1) * scale,
                                                   random.nextDouble(-1, 1) * scale), random.nextDouble(0.01, 0.1) * scale));
            }
            startedLower += compare(ObjectBVH.build(spheres, false), camera(random, c, scale), random, scale);
        }
        assertTrue(startedLower > 100, "few searches started below the root: " + startedLower);
    }

    private static Camera camera(SplittableRandom random, int c, double scale) {
        Point3D eye = new Point3D(random.nextDouble(-0.5, 0.5) * scale, random.nextDouble(-0.5, 0.5) * scale, 4 * scale);
        Point3D at = new Point3D(random.nextDouble(-0.3, 0.3) * scale, random.nextDouble(-0.3, 0.3) * scale, 0);
        return c % 2 == 0 ? new Pinhole(eye, at, Vector3D.UP, random.nextDouble(20, 60))
                          : new ThinLens(eye, at, Vector3D.UP, random.nextDouble(20, 60), 0.01 * scale, 4 * scale);
    }

    /** Compares, window by window, the view's hits with the whole tree's; returns how many windows started below the root. */
    private static int compare(GeometricObject whole, Camera camera, SplittableRandom random, double scale) {
        ShadeRec sr = BvhTesting.shadeRec();
        Ray ray = new Ray();
        int startedLower = 0;
        for (int w = 0; w < 40; w++) {
            double size = 1 + random.nextInt(48);
            double x0 = random.nextDouble(VP.hres() - size);
            double y0 = random.nextDouble(VP.vres() - size);
            List<HalfSpace> volume = camera.viewVolume(VP, x0, y0, x0 + size, y0 + size);
            GeometricObject view = whole.within(volume);
            if (view != null && view != whole) {
                startedLower++;
            }
            for (int k = 0; k < 50; k++) {
                double px = k < 4 ? x0 + (k % 2) * size : x0 + random.nextDouble() * size;
                double py = k < 4 ? y0 + (k / 2) * size : y0 + random.nextDouble() * size;
                double angle = random.nextDouble(2 * Math.PI);
                double r = k < 8 ? 1 : Math.sqrt(random.nextDouble());
                camera.generateRay(VP, px, py, r * Math.cos(angle), r * Math.sin(angle), ray);
                sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                long before = sr.boxTests;
                boolean hitWhole = whole.hit(ray, sr);
                long wholeTests = sr.boxTests - before;
                double t = sr.t;
                GeometricObject object = sr.object;
                int primitive = sr.primitive;
                sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
                before = sr.boxTests;
                boolean hitView = view != null && view.hit(ray, sr);
                String where = "scale " + scale + ", window " + w + ", ray " + k;
                assertEquals(hitWhole, hitView, where);
                assertTrue(sr.boxTests - before <= wholeTests, where);
                if (hitWhole) {
                    assertEquals(t, sr.t, where);
                    assertSame(object, sr.object, where);
                    assertEquals(primitive, sr.primitive, where);
                }
            }
        }
        return startedLower;
    }
}
