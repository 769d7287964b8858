package raytracer.api;

import java.io.Serializable;
import java.nio.file.Path;
import java.util.OptionalInt;
import java.util.function.Consumer;
import raytracer.accel.Aggregation;
import raytracer.cache.MeshCache;
import raytracer.core.PixelFilter;
import raytracer.core.RayTreeSettings;
import raytracer.core.Sampler;
import raytracer.core.ShadingPass;
import raytracer.core.ViewPlane;
import raytracer.image.DisplayEncoding;
import raytracer.image.Film;
import raytracer.samplers.Samplers;

/**
 * What a render changes in a scene file's settings, and how it searches and caches the scene: the
 * command line's options (render's, converge's and the Spark job's alike), so that an option means
 * the same wherever the scene is prepared. Plain names and numbers, checked when made (an
 * IllegalArgumentException names the option as the command line spells it), and serializable, so
 * a render farm's driver can send them to its workers. A null value leaves the scene's.
 *
 * @param width image width (--width)
 * @param height image height (--height)
 * @param samples samples per pixel (--spp)
 * @param sampler sample pattern (--sampler)
 * @param filter pixel filter (--filter, --filter-stddev)
 * @param maxDepth deepest recursion (--max-depth)
 * @param pass the first hit's terms (--pass)
 * @param cutoff the ray tree's cutoff (--cutoff)
 * @param encoding the PNG's encoding (--encoding)
 * @param lightSamples every area light's samples per shaded point, in place of its own (converge's light-samples)
 * @param accel how the objects are searched (--accel; never null)
 * @param analyse false for --no-skip: the scene analysis does not run
 * @param costView true for --view bvh-cost
 * @param seed the random seed (--seed)
 * @param meshCache the mesh cache's folder, or null for none (--no-cache)
 * @param meshCacheMax the bytes the mesh cache's entries may take together
 */
public record SceneOptions(Integer width, Integer height, Integer samples, String sampler, FilterChoice filter, Integer maxDepth,
                           String pass, Double cutoff, String encoding, Integer lightSamples, String accel, boolean analyse,
                           boolean costView, long seed, String meshCache, long meshCacheMax) implements Serializable {
    private static final long serialVersionUID = 2L;

    /** The scene as its file gives it, the default search and seed, and no mesh cache. */
    public static final SceneOptions NONE = new SceneOptions(null, null, null, null, new FilterChoice(null, null), null, null, null,
                                                             null, null, "auto", true, false, 1, null, MeshCache.DEFAULT_MAX_BYTES);

    public SceneOptions {
        requireAtLeast("--width", width, 1);
        requireAtLeast("--height", height, 1);
        requireWithin("--spp", samples, 1, Sampler.MAX_SAMPLES);
        requireWithin("--max-depth", maxDepth, 0, ViewPlane.MAX_DEPTH);
        requireWithin("light-samples", lightSamples, 1, Sampler.MAX_SAMPLES);
        if (cutoff != null && !(cutoff >= 0 && cutoff < 1)) {
            throw new IllegalArgumentException("--cutoff must be in [0, 1), got " + cutoff);
        }
        if (width != null && height != null && (long) width * height > Film.MAX_PIXELS) {
            throw new IllegalArgumentException("--width x --height is " + (long) width * height + " pixels, more than one image holds ("
                                               + Film.MAX_PIXELS + ")");
        }
        if (filter == null) {
            filter = new FilterChoice(null, null);
        } else {
            FilterChoice.parse(filter.name(), filter.stddev());
        }
        if (accel == null) {
            accel = "auto";
        }
        Aggregation.Mode.parse(accel);
        if (pass != null) {
            ShadingPass.parse(pass);
        }
        if (encoding != null) {
            parseEncoding(encoding);
        }
        if (sampler != null) {
            Samplers.byName(sampler);
        }
        if (meshCache != null && meshCache.isEmpty()) {
            // an empty path is the working directory, which is no place for cache files
            throw new IllegalArgumentException("--cache-dir must name a folder, got an empty name");
        }
    }

    private static void requireWithin(String option, Integer value, int min, int max) {
        if (value != null && (value < min || value > max)) {
            throw new IllegalArgumentException(option + " must be " + min + " to " + max + ", got " + value);
        }
    }

    private static void requireAtLeast(String option, Integer value, int min) {
        if (value != null && value < min) {
            throw new IllegalArgumentException(option + " must be at least " + min + ", got " + value);
        }
    }

    static DisplayEncoding parseEncoding(String encoding) {
        return DisplayEncoding.named(encoding).orElseThrow(() -> new IllegalArgumentException(
            "unknown --encoding '" + encoding + "'; allowed: " + DisplayEncoding.NAMES));
    }

    /** These options with the image's size set to {@code width} x {@code height}. */
    public SceneOptions withSize(int width, int height) {
        return edit(o -> {
            o.width = width;
            o.height = height;
        });
    }

    /** These options with {@code samples} per pixel. */
    public SceneOptions withSamples(int samples) {
        return edit(o -> o.samples = samples);
    }

    /** These options with the filter {@code name} ({@code stddev}: null for its own width). */
    public SceneOptions withFilter(String name, Double stddev) {
        return edit(o -> o.filter = new FilterChoice(name, stddev));
    }

    /** These options with the sample pattern {@code sampler}, the cutoff and the area lights' samples; a null keeps the value. */
    public SceneOptions withSampling(String sampler, Double cutoff, Integer lightSamples) {
        return edit(o -> {
            o.sampler = sampler != null ? sampler : o.sampler;
            o.cutoff = cutoff != null ? cutoff : o.cutoff;
            o.lightSamples = lightSamples != null ? lightSamples : o.lightSamples;
        });
    }

    /** These options with the mesh cache in {@code folder} (null: none). */
    public SceneOptions withMeshCache(Path folder) {
        return edit(o -> o.meshCache = folder == null ? null : folder.toString());
    }

    /** These options with the mesh cache in this user's default folder on this machine ({@link MeshCache#defaultDir}). */
    public SceneOptions withDefaultMeshCache() {
        return withMeshCache(MeshCache.defaultDir(System.getenv(), System.getProperty("user.home")));
    }

    /**
     * The view plane with the overridden sampler, size, samples, depth and filter; the cost view
     * counts per pixel, with the box filter, not averages blurred over the neighbours.
     */
    public ViewPlane viewPlane(ViewPlane scene) {
        ViewPlane vp = scene;
        if (sampler != null) {
            vp = vp.withSampler(Samplers.byName(sampler)); // before the count, which is rounded for the sampler
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
        vp = vp.withFilter(filter.applyTo(vp.filter()));
        if (costView) {
            vp = vp.withFilter(PixelFilter.BOX);
        }
        return vp;
    }

    /** How much of the ray tree to trace: the scene's, with the pass and the cutoff overridden. */
    public RayTreeSettings rayTree(RayTreeSettings scene) {
        RayTreeSettings settings = scene;
        if (pass != null) {
            settings = settings.withPass(ShadingPass.parse(pass));
        }
        if (cutoff != null) {
            settings = settings.withCutoff(cutoff);
        }
        return settings;
    }

    /** The PNG's encoding: the scene's unless overridden. */
    public DisplayEncoding encoding(DisplayEncoding scene) {
        return encoding != null ? parseEncoding(encoding) : scene;
    }

    /** The area lights' samples in place of their own, or empty for theirs. */
    public OptionalInt areaLightSamples() {
        return lightSamples == null ? OptionalInt.empty() : OptionalInt.of(lightSamples);
    }

    public Aggregation.Mode accelMode() {
        return Aggregation.Mode.parse(accel);
    }

    /** The mesh cache, or null without one. */
    public MeshCache openMeshCache() {
        return meshCache == null ? null : MeshCache.in(Path.of(meshCache), meshCacheMax);
    }

    /** These options with {@code change} made to a copy of their values, checked again. */
    private SceneOptions edit(Consumer<Values> change) {
        Values o = new Values(this);
        change.accept(o);
        return new SceneOptions(o.width, o.height, o.samples, o.sampler, o.filter, maxDepth, pass, o.cutoff, encoding, o.lightSamples,
                                accel, analyse, costView, seed, o.meshCache, meshCacheMax);
    }

    /** The values a {@code with} method may change, as a copy to change. */
    private static final class Values {
        Integer width;
        Integer height;
        Integer samples;
        String sampler;
        FilterChoice filter;
        Double cutoff;
        Integer lightSamples;
        String meshCache;

        Values(SceneOptions o) {
            width = o.width;
            height = o.height;
            samples = o.samples;
            sampler = o.sampler;
            filter = o.filter;
            cutoff = o.cutoff;
            lightSamples = o.lightSamples;
            meshCache = o.meshCache;
        }
    }
}
