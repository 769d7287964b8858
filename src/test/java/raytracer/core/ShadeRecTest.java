package raytracer.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.math.BBox;
import raytracer.math.Ray;

/** The completion of a hit: which face the ray came from, and the normals turned towards it. */
class ShadeRecTest {

    /** A surface met at t = 1 whose normal at the hit is the one it was given, whatever the ray. */
    private static final class FixedNormal extends GeometricObject {
        private final double nx;
        private final double ny;
        private final double nz;

        FixedNormal(double nx, double ny, double nz) {
            this.nx = nx;
            this.ny = ny;
            this.nz = nz;
        }

        @Override
        public boolean hit(Ray ray, ShadeRec sr) {
            return recordIfCloser(1, sr);
        }

        @Override
        public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
            return 1 < tMax;
        }

        @Override
        public void completeHit(Ray ray, ShadeRec sr) {
            sr.hitPoint.set(ray.atX(1), ray.atY(1), ray.atZ(1));
            sr.hitError.set(1e-16, 1e-16, 1e-16);
            sr.normal.set(nx, ny, nz);
            sr.geometricNormal.set(nx, ny, nz);
        }

        @Override
        public BBox boundingBox() {
            return new BBox(-1, -1, -1, 1, 1, 1);
        }
    }

    private static ShadeRec complete(GeometricObject object, Ray ray) {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 2, 1), null, null);
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        assertTrue(object.hit(ray, sr));
        sr.complete(ray);
        return sr;
    }

    @Test
    void theFaceIsTheSideTheRayCameFrom() {
        Ray down = new Ray().set(0, 0, 1, 0, 0, -1);
        ShadeRec front = complete(new FixedNormal(0, 0, 1), down);
        assertTrue(front.frontFace);
        assertEquals(1, front.normal.z, 0);
        ShadeRec back = complete(new FixedNormal(0, 0, -1), down);
        assertFalse(back.frontFace);
        assertEquals(1, back.normal.z, 0, "turned to face the ray");
        assertEquals(1, back.geometricNormal.z, 0);
    }

    /**
     * A ray along the surface has not crossed it: it is taken as seen from the front, the side it
     * has been on, and its continuation starts on that side (as a back face, glass applied Beer's
     * law over the whole way from the ray's origin).
     */
    @Test
    void aRayAlongTheSurfaceSeesItsFrontAndGoesOnOutside() {
        Ray along = new Ray().set(0, 0, 0, 1, 0, 0);
        for (double[] n : new double[][] {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}}) {
            ShadeRec sr = complete(new FixedNormal(n[0], n[1], n[2]), along);
            assertTrue(sr.frontFace, "normal " + n[0] + ", " + n[1] + ", " + n[2]);
            assertEquals(n[2], sr.normal.z, 0, "not turned");
            Ray next = sr.spawnRay(1, 0, 0, new Ray());
            assertTrue(next.oy * n[1] + next.oz * n[2] > 0, "the continuation starts on the normal's side");
        }
    }
}
