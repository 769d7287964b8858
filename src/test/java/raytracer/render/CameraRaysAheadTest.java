package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import raytracer.core.Camera;
import raytracer.core.PixelSamples;
import raytracer.core.Tracer;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.SampleMapping;
import raytracer.samplers.Samplers;

/**
 * The renderer makes a block of camera rays before it traces the first of them
 * ({@link WorkerScratch#CAMERA_RAYS}): each sample must still be traced with its own ray, made
 * from its own pixel position and lens point, and every sample exactly once, also in a last block
 * that is not full.
 */
class CameraRaysAheadTest {
    /** Not a multiple of the block: the last block of each pixel holds 37 mod 16 = 5 samples. */
    private static final int SPP = 37;

    @Test
    void eachSampleIsTracedWithItsOwnCameraRay() {
        AtomicLong traced = new AtomicLong();
        AtomicLong wrong = new AtomicLong();
        ViewPlane vp = new ViewPlane(3, 2, SPP, Samplers.byName("random"), 1, 1);
        World world = new World(vp, new InputCamera(), new Ambient(0, RGBColor.WHITE));
        world.setTracer(w -> new Checker(traced, wrong));
        world.prepare();
        Film film = new Film(3, 2);
        RenderStats stats = Renders.render(world, 2, 5, film);
        assertEquals(3L * 2 * SPP, traced.get(), "samples traced");
        assertEquals(3L * 2 * SPP, stats.primaryRays());
        assertEquals(0, wrong.get(), "samples traced with another sample's ray");
    }

    /** A camera that writes what it was given into the ray: (px, py, lensX) as origin, (lensY, 0, 0) as direction. */
    private static final class InputCamera implements Camera {
        @Override
        public void generateRay(ViewPlane vp, double px, double py, double lensX, double lensY, Ray out) {
            out.set(px, py, lensX, lensY, 0, 0);
        }

        @Override
        public boolean needsLensSamples() {
            return true;
        }
    }

    /** Draws the current sample's position and lens point again and counts the rays that were not made from them. */
    private static final class Checker implements Tracer {
        private final AtomicLong traced;
        private final AtomicLong wrong;

        Checker(AtomicLong traced, AtomicLong wrong) {
            this.traced = traced;
            this.wrong = wrong;
        }

        @Override
        public void traceRay(Ray ray, int depth, WorkerScratch scratch, MutableRgb out) {
            traced.incrementAndGet();
            PixelSamples samples = scratch.samples;
            samples.get2D(0, PixelSamples.PIXEL, 0, 1);
            // px = x + u for the pixel's integer x, so its fraction is u up to the rounding of the sum
            boolean position = Math.abs(ray.ox - Math.floor(ray.ox) - samples.u) < 1e-9
                               && Math.abs(ray.oy - Math.floor(ray.oy) - samples.v) < 1e-9;
            samples.get2D(0, PixelSamples.LENS, 0, 1);
            MutableVec3 disk = new MutableVec3();
            SampleMapping.toUnitDisk(samples.u, samples.v, disk);
            if (!position || ray.oz != disk.x || ray.dx != disk.y) {
                wrong.incrementAndGet();
            }
            out.setBlack();
        }
    }
}
