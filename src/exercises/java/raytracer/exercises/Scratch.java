package raytracer.exercises;

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

/**
 * A small world and one worker's scratch, to call an object, a light or a BRDF the way the renderer
 * does: single rays searched and completed, a hit record to shade.
 */
final class Scratch {
    final World world;
    final WorkerScratch worker;
    final ShadeRec sr;

    /** A world holding {@code objects}, searched as a plain list. */
    Scratch(GeometricObject... objects) {
        world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 2, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        for (GeometricObject object : objects) {
            world.addObject(object);
        }
        world.prepare();
        worker = new WorkerScratch(world);
        sr = worker.shadeRec(0);
    }

    static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray().set(ox, oy, oz, dx, dy, dz);
    }

    /** The hit of {@code object} alone along {@code ray}, completed as the world completes it, or null for a miss. */
    ShadeRec hit(GeometricObject object, Ray ray) {
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        if (!object.hit(ray, sr)) {
            return null;
        }
        sr.complete(ray);
        return sr;
    }

    /**
     * Places the hit record on a surface at {@code (x, y, z)} with unit normal {@code (nx, ny, nz)},
     * as a completed hit seen from the normal's side, for shading code to read.
     */
    ShadeRec surfacePoint(double x, double y, double z, double nx, double ny, double nz) {
        sr.hitPoint.set(x, y, z);
        sr.localHitPoint.set(x, y, z);
        sr.normal.set(nx, ny, nz);
        sr.geometricNormal.set(nx, ny, nz);
        sr.hitError.set(0, 0, 0);
        sr.frontFace = true;
        sr.depth = 0;
        sr.ray = ray(x + nx, y + ny, z + nz, -nx, -ny, -nz);
        return sr;
    }
}
