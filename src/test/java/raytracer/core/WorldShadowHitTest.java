package raytracer.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.math.BBox;
import raytracer.math.Ray;

/**
 * World.shadowHit leaves out the object that was hit only when that object cannot shadow a ray
 * leaving it towards its lit side: probes that always answer "in shadow" and count their tests
 * show which objects were asked.
 */
class WorldShadowHitTest {

    /** The plane z = 0, normal +z, whose shadow test always finds an occluder. */
    private static final class Probe extends GeometricObject {
        private final boolean cannotShadowItself;
        private final boolean closed;
        int shadowTests;

        Probe(boolean cannotShadowItself, boolean closed) {
            this.cannotShadowItself = cannotShadowItself;
            this.closed = closed;
        }

        @Override
        public boolean hit(Ray ray, ShadeRec sr) {
            double t = -ray.oz / ray.dz;
            return t > 0 && recordIfCloser(t, sr);
        }

        @Override
        public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
            shadowTests++;
            return true;
        }

        @Override
        public void completeHit(Ray ray, ShadeRec sr) {
            sr.hitPoint.set(ray.atX(sr.t), ray.atY(sr.t), 0);
            sr.hitError.set(0, 0, 0);
            sr.normal.set(0, 0, 1);
            sr.geometricNormal.set(0, 0, 1);
        }

        @Override
        public BBox boundingBox() {
            return new BBox(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, 0, Double.POSITIVE_INFINITY,
                            Double.POSITIVE_INFINITY, 0);
        }

        @Override
        public boolean cannotShadowItself() {
            return cannotShadowItself;
        }

        @Override
        public boolean isClosed() {
            return closed;
        }
    }

    /** The hit of a ray along z (down from z = 1 when {@code fromFront}, up from z = -1 otherwise) on the first probe. */
    private static ShadeRec hitFirst(World world, boolean fromFront) {
        world.prepare();
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        Ray ray = new Ray().set(0, 0, fromFront ? 1 : -1, 0, 0, fromFront ? -1 : 1);
        assertTrue(world.hit(ray, sr));
        return sr;
    }

    private static World world(GeometricObject... objects) {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 2, 1), null, null);
        for (GeometricObject object : objects) {
            world.addObject(object);
        }
        return world;
    }

    private static boolean shadowRayFrom(ShadeRec sr) {
        Ray shadow = sr.spawnRay(sr.geometricNormal.x, sr.geometricNormal.y, sr.geometricNormal.z, new Ray());
        return sr.world.shadowHit(shadow, 10, sr);
    }

    @Test
    void anObjectThatCannotShadowItselfIsNotAskedButTheOthersAre() {
        Probe hit = new Probe(true, false);
        World world = world(hit);
        assertFalse(shadowRayFrom(hitFirst(world, true)), "only the object hit is a caster, and it was left out");
        assertEquals(0, hit.shadowTests);

        Probe other = new Probe(true, false);
        Probe first = new Probe(true, false);
        World two = world(first, other);
        assertTrue(shadowRayFrom(hitFirst(two, true)), "another caster still occludes");
        assertEquals(0, first.shadowTests);
        assertEquals(1, other.shadowTests);
    }

    @Test
    void anObjectThatMayShadowItselfIsAsked() {
        Probe hit = new Probe(false, false);
        assertTrue(shadowRayFrom(hitFirst(world(hit), true)));
        assertEquals(1, hit.shadowTests);
    }

    @Test
    void aClosedObjectIsLeftOutOnItsFrontFaceOnly() {
        Probe front = new Probe(true, true);
        assertFalse(shadowRayFrom(hitFirst(world(front), true)), "seen from outside, its lit side is the outside");
        Probe back = new Probe(true, true);
        ShadeRec sr = hitFirst(world(back), false);
        assertFalse(sr.frontFace);
        assertTrue(shadowRayFrom(sr), "seen from inside, the ray heads into the solid and may hit it again");
        assertEquals(1, back.shadowTests);
    }

    @Test
    void anObjectHitInsideAnInstanceIsAsked() {
        Probe hit = new Probe(true, false);
        ShadeRec sr = hitFirst(world(hit), true);
        // as an instance would after its content recorded the hit: the leaf is then placed elsewhere
        sr.pushTransform(new LocalFrame() {
            @Override
            public void toLocal(Ray in, Ray out) {
                out.set(in.ox, in.oy, in.oz, in.dx, in.dy, in.dz);
            }

            @Override
            public void toWorld(ShadeRec record) {
            }
        });
        assertTrue(shadowRayFrom(sr));
        assertEquals(1, hit.shadowTests);
    }
}
