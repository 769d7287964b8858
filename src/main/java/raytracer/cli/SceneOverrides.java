package raytracer.cli;

import raytracer.core.RayTreeSettings;
import raytracer.core.Sampler;
import raytracer.core.ShadingPass;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.DisplayEncoding;

/**
 * What the command line changes in the scene file's settings: image size, samples, sampler,
 * filter and depth of the view plane, the term pass and the cutoff, the PNG encoding. A null field leaves the
 * scene's value.
 */
record SceneOverrides(Integer width, Integer height, Integer samples, Sampler sampler, FilterChoice filter, Integer maxDepth,
                      ShadingPass pass, Double cutoff, DisplayEncoding encoding) {

    /** Gives {@code world} the view plane with the overridden size, samples, sampler and depth. */
    void applyTo(World world) {
        ViewPlane vp = world.viewPlane();
        if (sampler != null) {
            vp = vp.withSampler(sampler); // before the count, which is rounded for the sampler
        }
        if (width != null || height != null) {
            vp = vp.withResolution(width != null ? width : vp.hres(), height != null ? height : vp.vres());
        }
        if (samples != null) {
            vp = vp.withSamples(samples);
        }
        if (maxDepth != null) {
            vp = vp.withMaxDepth(maxDepth);
        }
        if (filter != null) {
            vp = vp.withFilter(filter.applyTo(vp.filter()));
        }
        world.setViewPlane(vp);
    }

    RayTreeSettings rayTree(RayTreeSettings scene) {
        RayTreeSettings settings = scene;
        if (pass != null) {
            settings = settings.withPass(pass);
        }
        if (cutoff != null) {
            settings = settings.withCutoff(cutoff);
        }
        return settings;
    }

    DisplayEncoding encoding(DisplayEncoding scene) {
        return encoding != null ? encoding : scene;
    }
}
