package raytracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.Matrix4;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.shapes.Box;
import raytracer.shapes.Instance;
import raytracer.shapes.Plane;
import raytracer.shapes.Sphere;
import raytracer.shapes.mesh.Mesh;

/** A BVH over ordinary objects must find exactly what a plain list finds. */
class ObjectBVHTest {

    /** Overlapping spheres and boxes of sizes over three decades; every fifth casts no shadow. */
    private static List<GeometricObject> crowd(int n, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        List<GeometricObject> objects = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double size = Math.pow(10, r.nextDouble(-3, 0)) * 0.3;
            Point3D c = new Point3D(r.nextDouble(-2, 2), r.nextDouble(-2, 2), r.nextDouble(-2, 2));
            GeometricObject o = i % 3 == 0
                ? new Box(new Point3D(c.x() - size, c.y() - size, c.z() - size), new Point3D(c.x() + size, c.y() + size, c.z() + size))
                : new Sphere(c, size);
            o.setCastsShadows(i % 5 != 0);
            objects.add(o);
        }
        return objects;
    }

    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void closestAndAnyHitMatchALinearSearch(boolean sah) {
        List<GeometricObject> objects = crowd(300, 3);
        ObjectBVH bvh = ObjectBVH.build(objects, sah);
        ShadeRec sr = BvhTesting.shadeRec();
        ShadeRec brute = BvhTesting.shadeRec();
        SplittableRandom r = new SplittableRandom(17);
        Ray ray = new Ray();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            ray.set(r.nextDouble(-3, 3), r.nextDouble(-3, 3), r.nextDouble(-3, 3),
                    r.nextDouble(-1, 1), r.nextDouble(-1, 1), r.nextDouble(-1, 1));
            brute.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            boolean anyShadowCaster = false;
            for (GeometricObject o : objects) {
                o.hit(ray, brute);
                anyShadowCaster |= o.castsShadows() && o.shadowHit(ray, Double.POSITIVE_INFINITY, brute);
            }
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            boolean hit = bvh.hit(ray, sr);
            assertEquals(brute.hitAnObject(), hit, "ray " + i);
            assertEquals(anyShadowCaster, bvh.shadowHit(ray, Double.POSITIVE_INFINITY, sr), "shadow ray " + i);
            if (hit) {
                hits++;
                assertEquals(brute.t, sr.t, 0, "closest distance, ray " + i);
                assertSame(brute.object, sr.object, "closest object, ray " + i);
                double tMax = sr.t * r.nextDouble(0.2, 3);
                assertEquals(shadowBefore(objects, ray, tMax, brute), bvh.shadowHit(ray, tMax, sr),
                             "a shadow ray of limited length, ray " + i);
            }
        }
        assertTrue(hits > 2_000, "the test rays hit something often enough: " + hits);
    }

    /**
     * A BVH over instanced mesh BVHs: each search of a mesh runs inside a search of the scene's
     * tree and must leave the outer one's stack as it found it.
     */
    @Test
    void nestedSearchesOfMeshesUnderInstancesMatchALinearSearch() {
        Mesh sphere = Icosphere.make(2);
        SplittableRandom r = new SplittableRandom(71);
        List<GeometricObject> objects = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            MeshBVH mesh = new MeshBVH(sphere, new MedianSplitBuilder(4).build(MeshBVH.triangleBoxes(sphere)), List.of());
            double size = r.nextDouble(0.05, 0.5);
            Matrix4 place = Matrix4.translate(r.nextDouble(-2, 2), r.nextDouble(-2, 2), r.nextDouble(-2, 2))
                .multiply(Matrix4.scale(size, size, size));
            objects.add(new Instance(mesh, place));
        }
        ObjectBVH bvh = ObjectBVH.build(objects, false);
        ShadeRec sr = BvhTesting.shadeRec();
        ShadeRec brute = BvhTesting.shadeRec();
        Ray ray = new Ray();
        int hits = 0;
        for (int i = 0; i < 5_000; i++) {
            ray.set(r.nextDouble(-3, 3), r.nextDouble(-3, 3), r.nextDouble(-3, 3),
                    r.nextDouble(-1, 1), r.nextDouble(-1, 1), r.nextDouble(-1, 1));
            brute.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            for (GeometricObject o : objects) {
                o.hit(ray, brute);
            }
            sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
            assertEquals(brute.hitAnObject(), bvh.hit(ray, sr), "ray " + i);
            assertEquals(brute.t, sr.t, 0, "closest distance, ray " + i);
            assertEquals(brute.hitAnObject(), bvh.shadowHit(ray, Double.POSITIVE_INFINITY, sr), "shadow ray " + i);
            hits += brute.hitAnObject() ? 1 : 0;
        }
        assertTrue(hits > 500, "the test rays hit something often enough: " + hits);
    }

    private static boolean shadowBefore(List<GeometricObject> objects, Ray ray, double tMax, ShadeRec sr) {
        for (GeometricObject o : objects) {
            if (o.castsShadows() && o.shadowHit(ray, tMax, sr)) {
                return true;
            }
        }
        return false;
    }

    @Test
    void organizeKeepsPlanesOutsideTheBvhAndHonoursTheMode() {
        Plane ground = new Plane(new Point3D(0, -3, 0), new Normal(0, 1, 0));
        List<GeometricObject> many = new ArrayList<>(crowd(Aggregation.AUTO_THRESHOLD, 5));
        many.add(ground);
        List<GeometricObject> few = new ArrayList<>(crowd(Aggregation.AUTO_THRESHOLD - 1, 5));
        few.add(ground);

        assertSame(many, Aggregation.organize(many, Aggregation.Mode.LIST));
        assertSame(few, Aggregation.organize(few, Aggregation.Mode.AUTO), "below the threshold a list is faster");
        for (Aggregation.Mode mode : List.of(Aggregation.Mode.AUTO, Aggregation.Mode.MEDIAN, Aggregation.Mode.SAH)) {
            List<GeometricObject> organized = Aggregation.organize(many, mode);
            assertEquals(2, organized.size(), mode + ": one BVH and the plane");
            assertInstanceOf(ObjectBVH.class, organized.get(0), mode.toString());
            assertSame(ground, organized.get(1), mode.toString());
        }
        assertEquals(2, Aggregation.organize(few, Aggregation.Mode.MEDIAN).size(), "an explicit BVH is built even for few objects");
        assertThrows(IllegalArgumentException.class, () -> ObjectBVH.build(List.of(ground), false));
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class, () -> Aggregation.Mode.parse("kd-tree"));
        assertTrue(bad.getMessage().contains("auto, list, median, sah"), bad.getMessage());
        assertEquals(Aggregation.Mode.SAH, Aggregation.Mode.parse(" Sah "));
    }
}
