package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import raytracer.cameras.Orthographic;
import raytracer.core.Material;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadingPass;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.AreaLight;
import raytracer.lights.Ambient;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.Renders;
import raytracer.samplers.MultiJittered;
import raytracer.samplers.Regular;
import raytracer.shapes.Plane;
import raytracer.shapes.Rectangle;
import raytracer.tracers.AreaLighting;

/**
 * A glossy surface gets its highlight from every light (under an area light it had one
 * only where its glossy rays happened to hit the light's visible surface, so none from an
 * invisible light, at max depth 0, in the direct pass or where the cutoff pruned the rays).
 * Where its glossy rays cannot find the light, the glossy material's image is Phong's for the same
 * lobe, to the bit. Where they can (a visible light), the light's samples and the glossy rays are
 * weighed by multiple importance sampling, and a glossy floor seen from above shows the highlight
 * of the reflection integral, computed here by quadrature over the light, once: not twice, not
 * half.
 */
class GlossyHighlightTest {
    private static final double KS = 0.5;
    private static final double EXP = 20;
    private static final double LE = 3;

    /** A glossy or Phong floor (ka = kd = 0: the lobe alone) under a 1 x 1 light at height 1, seen from above. */
    private static World world(Material floorMaterial, boolean visible, int size, int samples, int maxDepth) {
        World world = new World(new ViewPlane(size, size, samples, samples == 1 ? new Regular() : new MultiJittered(), maxDepth, 1),
                                new Orthographic(new Point3D(0, 0.5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 2),
                                new Ambient(0, RGBColor.WHITE));
        world.setTracer(AreaLighting::new);
        Plane floor = new Plane(Point3D.ORIGIN, new Normal(0, 1, 0));
        floor.setMaterial(floorMaterial);
        world.addObject(floor);
        Point3D corner = new Point3D(-0.5, 1, -0.5);
        // a x b = (0, -1, 0): it emits downwards
        Vector3D a = new Vector3D(1, 0, 0);
        Vector3D b = new Vector3D(0, 0, 1);
        AreaLight light = AreaLight.rectangle(corner, a, b, LE, RGBColor.WHITE, 16);
        world.addLight(light);
        if (visible) {
            Rectangle face = new Rectangle(corner, a, b);
            face.setMaterial(new Emissive(LE, RGBColor.WHITE, light));
            face.setCastsShadows(false);
            world.addObject(face);
        }
        world.prepare();
        return world;
    }

    private static GlossyReflector glossy() {
        return new GlossyReflector(0, 0, RGBColor.BLACK, KS, RGBColor.WHITE, EXP, 8, true);
    }

    private static Phong phong() {
        return new Phong(0, 0, RGBColor.BLACK, KS, RGBColor.WHITE, EXP, true);
    }

    private static Film render(World world, RayTreeSettings settings, int size) {
        Film film = new Film(size, size);
        Renders.render(world, settings, 2, 5, film);
        return film;
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"invisible light", "max depth 0", "direct pass", "cutoff pruning the glossy rays"})
    void whereNoGlossyRayCanFindTheLightTheHighlightIsPhongs(String how) {
        int size = 16;
        boolean visible = !how.equals("invisible light");
        int depth = how.equals("max depth 0") ? 0 : 2;
        RayTreeSettings settings = switch (how) {
            case "direct pass" -> RayTreeSettings.FULL_TREE.withPass(ShadingPass.DIRECT);
            // a glossy ray weighs about ks / 8 = 0.06: pruned below 0.1
            case "cutoff pruning the glossy rays" -> RayTreeSettings.FULL_TREE.withCutoff(0.1);
            default -> RayTreeSettings.FULL_TREE;
        };
        Film glossy = render(world(glossy(), visible, size, 4, depth), settings, size);
        Film phong = render(world(phong(), visible, size, 4, depth), settings, size);
        double peak = 0;
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(phong.get(x, y, c), glossy.get(x, y, c), 1e-12 * phong.get(x, y, c), how + ": pixel " + x + "," + y);
                }
                peak = Math.max(peak, glossy.get(x, y, 0));
            }
        }
        assertTrue(peak > 0.5, how + ": no highlight, peak " + peak);
    }

    /**
     * Pixel centres of a 24 x 24 image (regular sampler, 1 sample), each with 16 light samples and
     * 8 glossy rays: the mean over the pixels of (render - exact) must be within 4 standard errors
     * of 0, and the exact mean is many standard errors from 0 and from twice itself.
     */
    @Test
    void aVisibleLightsHighlightIsCountedOnce() {
        int size = 24;
        Film film = render(world(glossy(), true, size, 1, 2), RayTreeSettings.FULL_TREE, size);
        double sum = 0;
        double sumSquares = 0;
        double exactSum = 0;
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                // the orthographic camera maps the view's 2 x 2 units onto the floor: +x right, -z up the image
                double px = ((x + 0.5) / size * 2 - 1);
                double pz = -(1 - (y + 0.5) / size * 2);
                double exact = reflected(px, pz);
                double residual = film.get(x, y, 0) - exact;
                sum += residual;
                sumSquares += residual * residual;
                exactSum += exact;
            }
        }
        int n = size * size;
        double mean = sum / n;
        double standardError = Math.sqrt((sumSquares / n - mean * mean) / (n - 1));
        double exactMean = exactSum / n;
        assertTrue(Math.abs(mean) < 4 * standardError, "mean residual " + mean + " against a standard error of " + standardError
                                                         + " (exact mean " + exactMean + ")");
        assertTrue(exactMean > 20 * standardError, "the test cannot tell once from twice: exact mean " + exactMean
                                                   + ", standard error " + standardError);
    }

    /**
     * The reflection integral at floor point (x, 0, z) for the viewer straight above: over the
     * light's area, f L cos(theta_i) cos(theta_l) / d^2 with f = ks (e + 2) / (2 pi) cos^e(alpha);
     * with the viewer along the normal, cos(alpha) = cos(theta_i), and the light faces down, so
     * cos(theta_i) = cos(theta_l) = h / d. Midpoint rule on 400 x 400 cells.
     */
    private static double reflected(double x, double z) {
        int cells = 400;
        double sum = 0;
        for (int i = 0; i < cells; i++) {
            for (int j = 0; j < cells; j++) {
                double lx = -0.5 + (i + 0.5) / cells;
                double lz = -0.5 + (j + 0.5) / cells;
                double dx = lx - x;
                double dz = lz - z;
                double d2 = dx * dx + 1 + dz * dz;
                double cos = 1 / Math.sqrt(d2);
                sum += KS * (EXP + 2) / (2 * Math.PI) * Math.pow(cos, EXP) * LE * cos * cos / d2;
            }
        }
        return sum / (cells * cells);
    }
}
