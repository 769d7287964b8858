package raytracer.render;

import raytracer.core.RayTreeSettings;
import raytracer.core.World;
import raytracer.image.Film;

/** Renders for tests: a prepared world on a pool of its own, closed when the image is done. */
public final class Renders {
    private Renders() {
    }

    /** Every term of the whole ray tree. */
    public static RenderStats render(World world, int threads, long seed, Film film) {
        return render(world, RayTreeSettings.FULL_TREE, threads, seed, film);
    }

    public static RenderStats render(World world, RayTreeSettings rayTree, int threads, long seed, Film film) {
        try (Workers workers = new Workers(threads)) {
            return new Renderer(world, rayTree, workers, seed).render(film);
        }
    }
}
