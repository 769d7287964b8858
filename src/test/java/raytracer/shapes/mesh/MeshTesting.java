package raytracer.shapes.mesh;

import raytracer.cameras.Pinhole;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/** A ShadeRec outside of any render, for shooting single rays. */
final class MeshTesting {
    private MeshTesting() {
    }

    static ShadeRec shadeRec() {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 2, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        return new WorkerScratch(world).shadeRec(0);
    }
}
