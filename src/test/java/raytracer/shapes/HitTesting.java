package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.PropertyCheck.forAll;
import static raytracer.PropertyCheck.unitVector;

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

    /**
     * The faces the ray meets on its way through the object, 'F' for a front face and 'B' for a
     * back face, following it past each hit as glass of index 1 would (ShadeRec.spawnRay); at most 8.
     */
    String faces(GeometricObject object, Ray ray) {
        StringBuilder faces = new StringBuilder();
        Ray next = new Ray().set(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz);
        while (faces.length() < 8) {
            ShadeRec hit = hit(object, next);
            if (hit == null) {
                break;
            }
            faces.append(hit.frontFace ? 'F' : 'B');
            next = hit.spawnRay(next.dx, next.dy, next.dz, new Ray());
        }
        return faces.toString();
    }

    /**
     * The ray in direction d through the point {@code reach} d before p + s e, where s is the
     * largest offset along the unit e (perpendicular to d) at which the ray still hits the object,
     * found by bisection to the last double: it grazes the silhouette as closely as doubles allow.
     */
    Ray grazing(GeometricObject object, double[] p, double[] d, double[] e, double reach) {
        double inside = 0;
        double outside = reach;
        Ray ray = new Ray();
        while (true) {
            double mid = 0.5 * (inside + outside);
            if (mid == inside || mid == outside) {
                break;
            }
            at(ray, p, d, e, reach, mid);
            if (hit(object, ray) != null) {
                inside = mid;
            } else {
                outside = mid;
            }
        }
        return at(ray, p, d, e, reach, inside);
    }

    private static Ray at(Ray ray, double[] p, double[] d, double[] e, double reach, double s) {
        return ray.set(p[0] + s * e[0] - reach * d[0], p[1] + s * e[1] - reach * d[1], p[2] + s * e[2] - reach * d[2],
                       d[0], d[1], d[2]);
    }

    /**
     * Rays from every direction grazing the silhouette of a closed object (p inside it, the object
     * within {@code reach} of p) enter it before they leave: their faces alternate front, back, ...,
     * never a back face first. A last front face alone is allowed: its exit lies within rounding of
     * the entry, so the ray continued from just inside finds itself out.
     */
    void assertEntersBeforeLeaving(String property, GeometricObject object, double[] p, double reach) {
        forAll(property, 300, random -> {
            double[] d = unitVector(random);
            double[] e = unitVector(random);
            double de = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
            double[] side = {e[0] - de * d[0], e[1] - de * d[1], e[2] - de * d[2]};
            double length = Math.sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]);
            for (int k = 0; k < 3; k++) {
                side[k] /= length;
            }
            String faces = faces(object, grazing(object, p, d, side, reach));
            assertTrue(faces.matches("F(BF)*B?"), "faces along the ray: " + faces);
        });
    }

    /**
     * Rays meeting a flat shape at the point q at grazing angles (slopes 1e-2 to 1e-14 against its
     * plane, unit normal n, in-plane unit direction a): from the side n points to they hit its front
     * face, from the other side its back face, with the normal turned to face them; a ray lying in
     * the plane touches it without crossing and misses. Below {@code mustHitDownTo} slope a miss
     * is allowed, but never the wrong face: a triangle's test rejects a t within its own rounding
     * of the ray's start (Watertight), and at slope 1e-14 a start a unit away along the ray lies
     * within 1e-14 of the plane, where rounding cannot tell it from a start on the plane.
     */
    void assertGrazingFaces(GeometricObject flat, double[] q, double[] n, double[] a) {
        assertGrazingFaces(flat, q, n, a, 1e-14);
    }

    void assertGrazingFaces(GeometricObject flat, double[] q, double[] n, double[] a, double mustHitDownTo) {
        for (double slope : new double[] {1e-2, 1e-6, 1e-10, 1e-14}) {
            for (int side : new int[] {1, -1}) {
                // from q - a + side slope n towards q
                double[] d = {a[0] - side * slope * n[0], a[1] - side * slope * n[1], a[2] - side * slope * n[2]};
                Ray ray = ray(q[0] - d[0], q[1] - d[1], q[2] - d[2], d[0], d[1], d[2]);
                ShadeRec sr = hit(flat, ray);
                String what = "slope " + slope + " from the " + (side > 0 ? "front" : "back");
                if (sr == null && slope < mustHitDownTo) {
                    continue;
                }
                assertNotNull(sr, what);
                // a few ulps off the plane in the origin move the hit along the ray by that over the slope
                assertEquals(1, sr.t, 1e-15 / slope, what);
                assertEquals(side > 0, sr.frontFace, what);
                assertTrue(sr.geometricNormal.dot(d[0], d[1], d[2]) < 0, what + ": the normal faces the ray");
            }
        }
        Ray inPlane = ray(q[0] - a[0], q[1] - a[1], q[2] - a[2], a[0], a[1], a[2]);
        assertNull(hit(flat, inPlane), "a ray in the plane");
        assertFalse(shadowHit(flat, inPlane, Double.POSITIVE_INFINITY), "a shadow ray in the plane");
    }
}
