package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.exercises.Scratch.ray;

import java.lang.reflect.Constructor;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.shapes.Box;
import raytracer.shapes.Plane;
import raytracer.shapes.Sphere;
import raytracer.shapes.Triangle;

/**
 * Exercise 6: a regular grid (Suffern, chapter 22) over bounded objects, walked cell by cell along
 * the ray (Amanatides and Woo 1987). It must find exactly what a search of every object finds,
 * the same distance and the same object, while asking far fewer objects.
 */
@Tag("exercise")
class RegularGridExercise {
    private static Constructor<? extends GeometricObject> grid;

    private final Scratch scratch = new Scratch();

    @BeforeAll
    static void findTheClass() {
        grid = Student.constructor(6, "raytracer.accel.RegularGrid", GeometricObject.class, List.class);
    }

    private static GeometricObject grid(List<GeometricObject> objects) {
        return Student.create(grid, objects);
    }

    /** An object that counts the hit tests it is asked for. */
    private static final class Counted extends GeometricObject {
        private final GeometricObject inner;
        long tests;

        Counted(GeometricObject inner) {
            this.inner = inner;
        }

        @Override
        public boolean hit(Ray ray, ShadeRec sr) {
            tests++;
            return inner.hit(ray, sr);
        }

        @Override
        public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
            tests++;
            return inner.shadowHit(ray, tMax, sr);
        }

        @Override
        public void completeHit(Ray ray, ShadeRec sr) {
            inner.completeHit(ray, sr);
        }

        @Override
        public BBox boundingBox() {
            return inner.boundingBox();
        }
    }

    /** Spheres and boxes of sizes from 0.01 to 2.5, often overlapping, a few of them casting no shadow. */
    private static List<GeometricObject> scene(SplittableRandom random, int count) {
        List<GeometricObject> objects = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            double size = Math.pow(10, -2 + 2.4 * random.nextDouble());
            Point3D c = new Point3D(20 * random.nextDouble() - 10, 10 * random.nextDouble(), 20 * random.nextDouble() - 10);
            GeometricObject o = random.nextBoolean() ? new Sphere(c, size)
                : new Box(c, new Point3D(c.x() + size, c.y() + size * (0.1 + 0.9 * random.nextDouble()), c.z() + size));
            o.setCastsShadows(random.nextInt(10) > 0);
            objects.add(o);
        }
        return objects;
    }

    /**
     * A ray from inside or outside the scene's box, aimed near one of the objects; one in four runs
     * along a plane or an axis, with exact zeros in d.
     */
    private static Ray randomRay(SplittableRandom random, List<GeometricObject> objects) {
        Point3D target = objects.get(random.nextInt(objects.size())).boundingBox().center();
        double tx = target.x() + random.nextDouble() - 0.5;
        double ty = target.y() + random.nextDouble() - 0.5;
        double tz = target.z() + random.nextDouble() - 0.5;
        double ox = 40 * random.nextDouble() - 20;
        double oy = 20 * random.nextDouble() - 5;
        double oz = 40 * random.nextDouble() - 20;
        switch (random.nextInt(8)) {
            case 0 -> ox = tx;
            case 1 -> {
                oy = ty;
                oz = tz;
            }
            default -> { }
        }
        if (ox == tx && oy == ty && oz == tz) {
            ox -= 1;
        }
        return ray(ox, oy, oz, tx - ox, ty - oy, tz - oz);
    }

    private GeometricObject closestByList(List<GeometricObject> objects, Ray ray) {
        ShadeRec sr = scratch.sr;
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        for (GeometricObject o : objects) {
            o.hit(ray, sr);
        }
        return sr.object;
    }

    @Test
    void itFindsWhatASearchOfEveryObjectFinds() {
        SplittableRandom random = new SplittableRandom(22);
        List<GeometricObject> objects = scene(random, 400);
        GeometricObject g = grid(objects);
        ShadeRec sr = scratch.sr;
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            Ray r = randomRay(random, objects);
            GeometricObject expected = closestByList(objects, r);
            double expectedT = sr.t;
            sr.beginSearch(r, 0, Double.POSITIVE_INFINITY);
            boolean found = g.hit(r, sr);
            String ray = "400 objects, ray " + i + " from (" + r.ox + ", " + r.oy + ", " + r.oz + ") along (" + r.dx + ", " + r.dy
                         + ", " + r.dz + "): ";
            assertEquals(expected != null, found, ray + "hit() must return whether it recorded a hit; a search of every object "
                                                  + (expected == null ? "finds none" : "finds one at t = " + expectedT));
            assertSame(expected, sr.object, ray + "the closest object is " + expected + " at t = " + expectedT + ", the grid found "
                                            + sr.object + " at t = " + sr.t + " (a grid may stop only once the closest hit lies "
                                            + "within the cells walked)");
            assertEquals(expectedT, sr.t, 0, ray + "the closest hit is at t = " + expectedT + ", the grid recorded " + sr.t);
            hits += found ? 1 : 0;
            double tMax = 30 * random.nextDouble();
            boolean blocked = false;
            for (GeometricObject o : objects) {
                blocked |= o.castsShadows() && o.shadowHit(r, tMax, sr);
            }
            assertEquals(blocked, g.shadowHit(r, tMax, sr), ray + "shadowHit up to " + tMax + " must be " + blocked
                                                            + ", as a search of every object says (objects that cast no shadow block nothing)");
        }
        assertTrue(hits > 2000, "too few hits to judge: " + hits + " of 20,000 rays (more than 2000 expected)");
    }

    @Test
    void itLooksOnlyForHitsCloserThanTheOneAlreadyFound() {
        SplittableRandom random = new SplittableRandom(5);
        List<GeometricObject> objects = scene(random, 200);
        GeometricObject g = grid(objects);
        ShadeRec sr = scratch.sr;
        for (int i = 0; i < 2000; i++) {
            Ray r = randomRay(random, objects);
            if (closestByList(objects, r) == null) {
                continue;
            }
            double t = sr.t;
            sr.beginSearch(r, 0, t * 0.999);
            String ray = "ray " + i + ", its closest hit at t = " + t + ", searched with sr.t = " + (t * 0.999) + ": ";
            assertFalse(g.hit(r, sr), ray + "hit() must record only hits closer than sr.t, and return false");
            assertNull(sr.object, ray + "sr.object must stay null: a hit beyond sr.t was recorded");
        }
    }

    @Test
    void itAsksFarFewerObjectsThanAList() {
        SplittableRandom random = new SplittableRandom(7);
        List<GeometricObject> objects = new ArrayList<>();
        List<Counted> counted = new ArrayList<>();
        for (int i = 0; i < 2000; i++) {
            Counted c = new Counted(new Sphere(new Point3D(20 * random.nextDouble(), 20 * random.nextDouble(), 20 * random.nextDouble()), 0.2));
            counted.add(c);
            objects.add(c);
        }
        GeometricObject g = grid(objects);
        int rays = 2000;
        for (int i = 0; i < rays; i++) {
            Ray r = ray(-5, 20 * random.nextDouble(), 20 * random.nextDouble(), 1, random.nextDouble() - 0.5, random.nextDouble() - 0.5);
            scratch.sr.beginSearch(r, 0, Double.POSITIVE_INFINITY);
            g.hit(r, scratch.sr);
        }
        double perRay = counted.stream().mapToLong(c -> c.tests).sum() / (double) rays;
        assertTrue(perRay < 100, "2000 spheres of radius 0.2 in a cube of 20: a grid must test fewer than 100 objects per ray "
                                 + "(it walks the cells a ray pierces), tested " + perRay + " of " + objects.size());
    }

    @Test
    void aFlatSceneWorks() {
        // every triangle in the plane y = 0: the grid's box has no height
        SplittableRandom random = new SplittableRandom(3);
        List<GeometricObject> objects = new ArrayList<>();
        for (int i = 0; i < 300; i++) {
            double x = 10 * random.nextDouble();
            double z = 10 * random.nextDouble();
            objects.add(new Triangle(new Point3D(x, 0, z), new Point3D(x + 0.3, 0, z), new Point3D(x, 0, z + 0.3)));
        }
        GeometricObject g = grid(objects);
        for (int i = 0; i < 2000; i++) {
            Ray r = ray(10 * random.nextDouble(), 5, 10 * random.nextDouble(), random.nextDouble() - 0.5, -1, random.nextDouble() - 0.5);
            GeometricObject expected = closestByList(objects, r);
            scratch.sr.beginSearch(r, 0, Double.POSITIVE_INFINITY);
            g.hit(r, scratch.sr);
            assertSame(expected, scratch.sr.object, "300 triangles in the plane y = 0 (a grid one cell high), ray " + i + " down from ("
                                                    + r.ox + ", 5, " + r.oz + "): the closest triangle is " + expected + ", the grid found "
                                                    + scratch.sr.object);
        }
    }

    @Test
    void itsBoxHoldsEveryObject() {
        List<GeometricObject> objects = scene(new SplittableRandom(1), 50);
        BBox box = grid(objects).boundingBox();
        for (GeometricObject o : objects) {
            BBox b = o.boundingBox();
            assertTrue(box.contains(b.x0(), b.y0(), b.z0()) && box.contains(b.x1(), b.y1(), b.z1()),
                       "boundingBox() must hold every object's box: " + b + " sticks out of " + box);
        }
    }

    @Test
    void unboundedObjectsAreRefused() {
        List<GeometricObject> objects = new ArrayList<>(scene(new SplittableRandom(2), 3));
        objects.add(new Plane(Point3D.ORIGIN, new Normal(0, 1, 0)));
        assertThrows(IllegalArgumentException.class, () -> grid(objects),
                     "RegularGrid(3 objects and a plane): a plane has no box to put in cells, IllegalArgumentException");
    }
}
