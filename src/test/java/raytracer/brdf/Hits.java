package raytracer.brdf;

import raytracer.cameras.Pinhole;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/** Hit records and directions for testing BRDFs outside a render. */
final class Hits {
    private Hits() {
    }

    /** A hit record with the given unit shading normal. */
    static ShadeRec withNormal(double nx, double ny, double nz) {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 1, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.normal.set(nx, ny, nz).normalize();
        sr.geometricNormal.set(sr.normal);
        return sr;
    }

    /** The unit direction at polar angle {@code thetaDeg} from +z and azimuth {@code phiDeg}. */
    static MutableVec3 direction(double thetaDeg, double phiDeg) {
        double t = Math.toRadians(thetaDeg);
        double p = Math.toRadians(phiDeg);
        return new MutableVec3().set(Math.sin(t) * Math.cos(p), Math.sin(t) * Math.sin(p), Math.cos(t));
    }
}
