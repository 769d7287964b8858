package raytracer.shapes;

import raytracer.cameras.Pinhole;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/** Shoots single rays at one object and completes the hit, as the World does. */
final class HitTesting {
    private final ShadeRec sr;

    HitTesting() {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 2, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        sr = new WorkerScratch(world).shadeRec(0);
    }

    /** The hit record the tests fill, for tests of the intersection routines themselves. */
    ShadeRec record() {
        return sr;
    }

    static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray().set(ox, oy, oz, dx, dy, dz);
    }

    /** The completed hit, or null for a miss. */
    ShadeRec hit(GeometricObject object, Ray ray) {
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        if (!object.hit(ray, sr)) {
            return null;
        }
        sr.complete(ray);
        return sr;
    }

    boolean shadowHit(GeometricObject object, Ray ray, double tMax) {
        return object.shadowHit(ray, tMax, sr);
    }
}
