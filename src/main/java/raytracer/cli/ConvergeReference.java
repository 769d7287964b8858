package raytracer.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;
import java.util.function.BiFunction;
import raytracer.core.ViewPlane;
import raytracer.core.World;
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

    /** A .pfm file of the image's size with finite values; anything else is an IOException naming the file. */
    static Film fromFile(Path file, int width, int height) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new IOException("cannot read reference " + file + ": " + (Files.isDirectory(file) ? "it is a directory" : "no such file"));
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

    /**
     * The scene's exact image, its quadrature error noted on {@code note}; empty when the scene has
     * none, unless {@code required}, when the reader's reason is the exception.
     */
    static Optional<Film> closedForm(Path scene, int width, int height, PrintWriter note, boolean required)
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
        return Optional.of(film);
    }

    /**
     * The scene rendered at {@code spp} with seed {@code seed}, without a cutoff, read from the
     * cache when it is there and stored in it when not ({@code cache} null: neither).
     */
    static Film rendered(Path scene, byte[] sceneBytes, World world, int spp, long seed, ReferenceCache cache,
                         BiFunction<World, Film, RenderStats> render, PrintWriter note) throws IOException {
        ViewPlane vp = world.viewPlane().withSamples(spp);
        world.setViewPlane(vp);
        world.setCutoff(0);
        String settings = "width=" + vp.hres() + "\nheight=" + vp.vres() + "\nspp=" + vp.numSamples() + "\nseed=" + seed
                          + "\ncutoff=0\nsampler=" + Samplers.nameOf(vp.sampler()) + "\nexposure=" + vp.exposure() + "\n";
        Path file = cache == null ? null : cache.file(scene.getFileName().toString(), sceneBytes, settings);
        Optional<Film> cached = file == null ? Optional.empty() : cache.load(file);
        if (cached.isPresent() && cached.get().width() == vp.hres() && cached.get().height() == vp.vres()) {
            note.printf("converge: reference: %s (%d spp, seed %d; reused)%n", file, vp.numSamples(), seed);
            return cached.get();
        }
        note.printf("converge: rendering the reference: %d spp, seed %d, no cutoff%n", vp.numSamples(), seed);
        Film film = new Film(vp.hres(), vp.vres());
        RenderStats stats = render.apply(world, film);
        Film scaled = scaled(film, vp.exposure());
        if (file != null) {
            cache.store(file, scaled, 1, "reference image of " + scene.toAbsolutePath() + ", rendered by render converge\n" + settings);
            note.printf(Locale.ROOT, "converge: reference: rendered in %.1f s, saved as %s%n", stats.seconds(), file);
        } else {
            note.printf(Locale.ROOT, "converge: reference: rendered in %.1f s, not saved (--no-cache)%n", stats.seconds());
        }
        return scaled;
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
