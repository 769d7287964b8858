package raytracer.cli.converge;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import raytracer.api.SceneFrame;
import raytracer.cache.ContentStamp;
import raytracer.cache.ReferenceCache;
import raytracer.core.RayTreeSettings;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.ErrorMetrics;
import raytracer.image.FileKind;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.io.scene.ClosedFormReader;
import raytracer.io.scene.SceneException;
import raytracer.reference.LitPlane;
import raytracer.render.RenderStats;
import raytracer.samplers.Samplers;

/**
 * The image the convergence benchmark measures against, in the units of the renderer's .pfm output
 * (linear radiance times the scene's exposure): a given .pfm file, the scene's exact image when it
 * has one, or a render of the scene with many samples and another seed, cached for the next run.
 */
final class ConvergeReference {
    /** The Gauss-Legendre order per pixel of exact images; 4 x 4 estimates its error (see LitPlaneTest). */
    static final int CLOSED_FORM_ORDER = 8;

    private ConvergeReference() {
    }

    /**
     * The reference --reference asks for, of the prepared frame {@code base}: a .pfm file, the
     * scene's exact image (auto, when it has one and the filter is the box), or the scene rendered
     * (self, and auto otherwise, with seeds made from the measured renders' {@code seed}), read
     * from {@code cache} when it is there (null: --no-cache).
     */
    static Image choose(ConvergeCommand command, SceneFrame base, long seed, ReferenceCache cache, Renderings render, PrintWriter note)
            throws Exception {
        String reference = command.reference;
        Path scene = command.scene;
        ViewPlane vp = base.world().viewPlane();
        if (!List.of("auto", "closed-form", "self").contains(reference)) {
            Film film = fromFile(Path.of(reference), vp.hres(), vp.vres());
            note.println("converge: reference: " + reference);
            return new Image(film, Double.NaN, reference);
        }
        if (!vp.filter().isBox()) {
            // the exact images are averages over each pixel's square: a box-filtered image
            if (reference.equals("closed-form")) {
                throw new IOException("--reference closed-form: the exact image is of box-filtered pixels, and this run's filter is "
                                      + vp.filter().name() + "; use --filter box, or --reference self");
            }
            if (reference.equals("auto") && hasClosedForm(scene)) {
                note.println("converge: reference: the exact image is of box-filtered pixels, not " + vp.filter().name()
                             + "; rendering one instead");
            }
        } else if (!reference.equals("self")) {
            Optional<Image> exact = closedForm(scene, vp.hres(), vp.vres(), note, reference.equals("closed-form"));
            if (exact.isPresent()) {
                return exact.get();
            }
        }
        if (cache != null) {
            cache.checkFolder();
        }
        return rendered(scene, Files.readAllBytes(scene), base, command.referenceSpp, ~seed, cache, render, note);
    }

    /** A .pfm file of the image's size with finite values; anything else is an IOException naming the file. */
    static Film fromFile(Path file, int width, int height) throws IOException {
        String notRegular = FileKind.notRegular(file);
        if (notRegular != null || !Files.isRegularFile(file)) {
            throw new IOException("cannot read reference " + file + ": " + (notRegular != null ? notRegular : "no such file"));
        }
        Film film = ImageWriters.readPfm(file);
        if (film.width() != width || film.height() != height) {
            throw new IOException("reference " + file + " is " + film.width() + "x" + film.height() + " but the image is "
                                  + width + "x" + height + " (give -W " + film.width() + " -H " + film.height()
                                  + ", or a reference of the image's size)");
        }
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                for (int c = 0; c < 3; c++) {
                    if (!Float.isFinite(film.get(x, y, c))) {
                        throw new IOException("reference " + file + ": pixel (" + x + ", " + y + ") is not a finite number");
                    }
                }
            }
        }
        return film;
    }

    /** True when the scene's image has a closed form. */
    static boolean hasClosedForm(Path scene) {
        try {
            ClosedFormReader.read(scene);
            return true;
        } catch (SceneException e) {
            return false;
        }
    }

    /**
     * The scene's exact image, its quadrature error noted on {@code note}; empty when the scene has
     * none, unless {@code required}, when the reader's reason is the exception.
     */
    static Optional<Image> closedForm(Path scene, int width, int height, PrintWriter note, boolean required)
            throws SceneException {
        LitPlane exact;
        try {
            exact = ClosedFormReader.read(scene).withResolution(width, height);
        } catch (SceneException e) {
            if (required || !e.getMessage().contains("no closed form")) {
                throw e;
            }
            return Optional.empty();
        }
        Film film = exact.render(CLOSED_FORM_ORDER);
        Film coarse = exact.render(CLOSED_FORM_ORDER / 2);
        double worst = 0;
        double mean = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                for (int c = 0; c < 3; c++) {
                    worst = Math.max(worst, Math.abs(film.get(x, y, c) - coarse.get(x, y, c)));
                    mean += film.get(x, y, c) / (3.0 * width * height);
                }
            }
        }
        note.printf(Locale.ROOT, "converge: reference: the exact image (closed form), each pixel averaged by %dx%d-point "
                    + "Gauss-Legendre quadrature; %s%n", CLOSED_FORM_ORDER, CLOSED_FORM_ORDER,
                    worst == 0 ? "the " + CLOSED_FORM_ORDER / 2 + "x" + CLOSED_FORM_ORDER / 2 + " rule gives the same 32-bit values"
                    : String.format(Locale.ROOT, "the %dx%d rule differs by at most %.2g of the image's mean", CLOSED_FORM_ORDER / 2,
                                    CLOSED_FORM_ORDER / 2, mean > 0 ? worst / mean : worst));
        return Optional.of(new Image(film, 0, "exact (closed form)"));
    }

    /** The other seed of a self-rendered reference: {@code seed ^ OTHER_HALF} differs from the reference's seed and from ~seed. */
    static final long OTHER_HALF = 0x5DEECE66DL;

    /**
     * A reference and the RMSE of its own noise: 0 for an exact image, NaN when unknown (a file);
     * {@code what} says what it is, for the table.
     */
    record Image(Film film, double noiseRmse, String what) {
    }

    /**
     * The scene rendered without a cutoff in two independent halves of {@code spp / 2} samples,
     * seeds {@code seed} and {@code seed ^ OTHER_HALF}, averaged; the halves' difference measures the
     * average's own noise: with independent halves of equal variance, its RMSE is RMSE(a, b) / 2.
     * Read from the cache when it is there and stored in it when not ({@code cache} null: neither);
     * the frame number of an animated scene is part of the cache's key.
     */
    static Image rendered(Path scene, byte[] sceneBytes, SceneFrame loaded, int spp, long seed, ReferenceCache cache,
                          Renderings render, PrintWriter note) throws IOException {
        World world = loaded.world();
        ViewPlane vp = world.viewPlane().withSamples(Math.max(1, spp / 2));
        world.setViewPlane(vp);
        RayTreeSettings whole = loaded.rayTree().withCutoff(0);
        int frame = loaded.number();
        long other = seed ^ OTHER_HALF;
        String settings = "width=" + vp.hres() + "\nheight=" + vp.vres() + "\nspp=2 x " + vp.numSamples() + "\nseeds=" + seed + ", "
                          + other + "\ncutoff=0\nsampler=" + Samplers.nameOf(vp.sampler()) + "\nexposure=" + vp.exposure() + "\n"
                          + (vp.filter().isBox() ? "" : "filter=" + vp.filter().name() + "\nfilter-radius=" + vp.filter().radius() + "\n")
                          // frame 0 unnamed: the key of a still's reference, or of frame 0 of an animation, stays what it was
                          + (frame == 0 ? "" : "frame=" + frame + "\n")
                          + inputs(scene, loaded.report().inputs());
        String what = "self-rendered, 2 x " + vp.numSamples() + " spp";
        Path file = cache == null ? null : cache.file(scene.getFileName().toString(), sceneBytes, settings);
        Optional<ReferenceCache.Reference> cached = file == null ? Optional.empty()
            : cache.load(file, why -> note.println("converge: reference: the cached " + file + " " + why + "; rendering it again"));
        if (cached.isPresent() && cached.get().film().width() == vp.hres() && cached.get().film().height() == vp.vres()) {
            note.printf("converge: reference: %s (%s, seeds %d and %d; reused)%n", file, what, seed, other);
            return new Image(cached.get().film(), cached.get().noiseRmse(), what);
        }
        note.printf("converge: rendering the reference: 2 x %d spp, seeds %d and %d, no cutoff%n", vp.numSamples(), seed, other);
        Film a = new Film(vp.hres(), vp.vres());
        Film b = new Film(vp.hres(), vp.vres());
        double seconds = render.render(world, whole, seed, a, "reference, half 1 of 2").seconds()
                         + render.render(world, whole, other, b, "reference, half 2 of 2").seconds();
        a = scaled(a, vp.exposure());
        b = scaled(b, vp.exposure());
        double noiseRmse = ErrorMetrics.compare(a, 1, b).rmse() / 2;
        Film film = new Film(vp.hres(), vp.vres());
        for (int y = 0; y < vp.vres(); y++) {
            for (int x = 0; x < vp.hres(); x++) {
                film.set(x, y, (a.get(x, y, 0) + b.get(x, y, 0)) / 2.0, (a.get(x, y, 1) + b.get(x, y, 1)) / 2.0,
                         (a.get(x, y, 2) + b.get(x, y, 2)) / 2.0);
            }
        }
        if (file != null) {
            cache.store(file, film, noiseRmse, "reference image of " + scene.toAbsolutePath() + ", rendered by render converge\n"
                                               + settings);
            note.printf(Locale.ROOT, "converge: reference: rendered in %.1f s, saved as %s%n", seconds, file);
        } else {
            note.printf(Locale.ROOT, "converge: reference: rendered in %.1f s, not saved (--no-cache)%n", seconds);
        }
        return new Image(film, noiseRmse, what);
    }

    /**
     * One line per file the scene read besides itself (meshes, MTL files, textures, environment
     * maps), with its content's identity: a reference is rendered again when any of them changes,
     * as a mesh cache entry is rebuilt.
     */
    static String inputs(Path scene, List<Path> inputs) throws IOException {
        Path folder = scene.toAbsolutePath().normalize().getParent();
        Set<Path> files = new TreeSet<>();
        for (Path input : inputs) {
            files.add(input.toAbsolutePath().normalize());
        }
        files.remove(scene.toAbsolutePath().normalize());
        StringBuilder lines = new StringBuilder();
        for (Path file : files) {
            lines.append("input=").append(folder.relativize(file)).append(' ').append(ContentStamp.of(file, "").identity()).append('\n');
        }
        return lines.toString();
    }

    /** How the command renders: a world with its ray tree and a seed, into a film, under a progress label, returning what it cost. */
    @FunctionalInterface
    interface Renderings {
        RenderStats render(World world, RayTreeSettings rayTree, long seed, Film film, String label);
    }

    /** The film times {@code exposure}, as a .pfm of it would hold it. */
    static Film scaled(Film film, double exposure) {
        if (exposure == 1) {
            return film;
        }
        Film out = new Film(film.width(), film.height());
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                out.set(x, y, film.get(x, y, 0) * exposure, film.get(x, y, 1) * exposure, film.get(x, y, 2) * exposure);
            }
        }
        return out;
    }
}
