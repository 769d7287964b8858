package raytracer.render;

import raytracer.core.Camera;
import raytracer.core.PixelSamples;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.MutableVec3;
import raytracer.math.Ray;
import raytracer.math.SampleMapping;

/**
 * The camera rays of a pixel's samples, made a block ahead of tracing: at the first sample of each
 * block of {@link WorkerScratch#CAMERA_RAYS}, the rays of the whole block go into the worker's
 * camera-ray slots. A camera ray depends on nothing traced, and made in one loop, one ray's table
 * reads, square root and divisions overlap another's, where one sample at a time they headed its
 * chain of dependent arithmetic and the processor waited on them (1.12 times the samples per second on
 * 1 December 2026: docs/performance.md's history). Each ray's values are functions of its pixel,
 * sample index and dimension ({@link PixelSamples}), so making them early changes no bit.
 */
final class CameraRays {
    private final World world;

    CameraRays(World world) {
        this.world = world;
    }

    /**
     * The camera ray through sample {@code j} of the {@code n} of pixel (x, y); at the first sample
     * of a block, the block's rays are made.
     */
    Ray ray(int x, int y, int j, int n, WorkerScratch s) {
        int slot = j % WorkerScratch.CAMERA_RAYS;
        if (slot == 0) {
            make(x, y, j, Math.min(n, j + WorkerScratch.CAMERA_RAYS), s);
        }
        return s.cameraRay(slot);
    }

    /** Where in its pixel sample {@code j} lies, across (u) and down (v), for a filter wider than the pixel. */
    double u(int j, WorkerScratch s) {
        return s.pixelU[j % WorkerScratch.CAMERA_RAYS];
    }

    double v(int j, WorkerScratch s) {
        return s.pixelV[j % WorkerScratch.CAMERA_RAYS];
    }

    /** Makes the camera rays of samples {@code first} .. {@code end - 1} of pixel (x, y). */
    private void make(int x, int y, int first, int end, WorkerScratch s) {
        ViewPlane vp = world.viewPlane();
        Camera camera = world.camera();
        boolean lens = camera.needsLensSamples();
        PixelSamples samples = s.samples;
        MutableVec3 disk = s.diskScratch;
        for (int i = first; i < end; i++) {
            samples.startSample(i);
            samples.get2D(0, PixelSamples.PIXEL, 0, 1);
            s.pixelU[i - first] = samples.u;
            s.pixelV[i - first] = samples.v;
            double px = x + samples.u;
            double py = y + samples.v;
            Ray ray = s.cameraRay(i - first);
            if (lens) {
                // the concentric map keeps the pattern's strata (Suffern, section 10.4)
                samples.get2D(0, PixelSamples.LENS, 0, 1);
                SampleMapping.toUnitDisk(samples.u, samples.v, disk);
                camera.generateRay(vp, px, py, disk.x, disk.y, ray);
            } else {
                camera.generateRay(vp, px, py, 0, 0, ray);
            }
        }
    }
}
