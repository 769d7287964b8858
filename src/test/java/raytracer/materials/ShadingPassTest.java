package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.core.Material;
import raytracer.core.RayTreeSettings;
import raytracer.core.ShadingPass;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.PointLight;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.Renders;
import raytracer.shapes.Sphere;
import raytracer.tracers.Whitted;

/** The term passes split the first hit's radiance: their sum is the full image. */
class ShadingPassTest {
    private static final int SIZE = 21;

    private static Film render(Material material, ShadingPass pass) {
        World world = new World(new ViewPlane(SIZE, SIZE, 1, (n, rng, xs, ys) -> {
            xs[0] = 0.5;
            ys[0] = 0.5;
        }, 6, 1), new Orthographic(new Point3D(0, 0, 10), Point3D.ORIGIN, Vector3D.UP, 2.4), new Ambient(0.2, RGBColor.WHITE));
        world.setBackground(new RGBColor(0.2, 0.5, 0.9));
        Sphere sphere = new Sphere(Point3D.ORIGIN, 1);
        sphere.setMaterial(material);
        world.addObject(sphere);
        world.addLight(new PointLight(30, RGBColor.WHITE, new Point3D(2, 3, 5)));
        world.setTracer(Whitted::new);
        world.prepare();
        Film film = new Film(SIZE, SIZE);
        Renders.render(world, RayTreeSettings.FULL_TREE.withPass(pass), 1, 1, film);
        return film;
    }

    private static void assertSum(Material m, ShadingPass... parts) {
        Film full = render(m, ShadingPass.FULL);
        Film[] films = new Film[parts.length];
        for (int i = 0; i < parts.length; i++) {
            films[i] = render(m, parts[i]);
        }
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                for (int c = 0; c < 3; c++) {
                    double sum = 0;
                    for (Film f : films) {
                        sum += f.get(x, y, c);
                    }
                    // outside the sphere every pass shows the background once: count it once
                    double expected = full.get(x, y, c) + (isBackground(x, y) ? (parts.length - 1) * full.get(x, y, c) : 0);
                    assertEquals(expected, sum, 1e-5, "pixel " + x + "," + y);
                }
            }
        }
    }

    private static boolean isBackground(int x, int y) {
        double px = ((x + 0.5) / SIZE * 2 - 1) * 1.2;
        double py = (1 - (y + 0.5) / SIZE * 2) * 1.2;
        return px * px + py * py > 1;
    }

    @Test
    void mirrorDirectPlusReflectionIsTheWhole() {
        assertSum(new Reflective(0.2, 0.3, new RGBColor(0.5, 0.3, 0.1), 0.2, RGBColor.WHITE, 50, 0.5, RGBColor.WHITE, true),
                  ShadingPass.DIRECT, ShadingPass.REFLECTION);
    }

    @Test
    void glassDirectReflectionAndRefractionAreTheWhole() {
        assertSum(new Dielectric(1.5, RGBColor.gray(0.2), 0.5, 100), ShadingPass.DIRECT, ShadingPass.REFLECTION,
                  ShadingPass.REFRACTION);
    }

    @Test
    void magentaShowsTheReflectedFractionAndTheAblationDropsTheAngleDependence() {
        Material mirror = new Reflective(0, 0, RGBColor.BLACK, 0, RGBColor.WHITE, 10, 0.5, RGBColor.WHITE, true);
        Film magenta = render(mirror, ShadingPass.MAGENTA_REFLECTION);
        int c = SIZE / 2;
        assertEquals(0.5, magenta.get(c, c, 0), 1e-6, "Schlick at normal incidence: 0.5 of magenta");
        assertEquals(0, magenta.get(c, c, 1), 1e-6);
        double py = (1 - 2.5 / SIZE * 2) * 1.2;
        double cos = Math.sqrt(1 - py * py);
        assertEquals(raytracer.math.Fresnel.schlick(0.5, cos), magenta.get(c, 2, 0), 1e-6, "more towards the rim");
        assertTrue(magenta.get(c, 2, 0) > 0.53);
        Film flat = render(mirror, ShadingPass.NO_FRESNEL);
        // half the blue background at the centre and at the rim alike
        assertEquals(0.5 * 0.9, flat.get(c, c, 2), 1e-6);
        assertEquals(0.5 * 0.9, flat.get(c, 2, 2), 1e-6);
        Film glass = render(new Dielectric(1.5, RGBColor.BLACK, 0, 100), ShadingPass.NO_FRESNEL);
        // all refracted, nothing reflected: straight through the centre to the background
        assertEquals(0.9, glass.get(c, c, 2), 1e-6);
    }

    /**
     * A glossy sphere's rays see the magenta environment in that pass as the mirror's do (they
     * saw the scene's background): it adds the glossy weight's average times (1, 0, 1) to the
     * direct pass, where the full image adds it times the blue background. Its 4 rays are drawn
     * alike in every pass (the same pixel, sample and seed), so the identity holds ray for ray.
     */
    @Test
    void glossyRaysSeeMagentaInThatPass() {
        Material glossy = new GlossyReflector(0.2, 0.3, new RGBColor(0.5, 0.3, 0.1), 0.5, RGBColor.WHITE, 20, 4, false);
        Film magenta = render(glossy, ShadingPass.MAGENTA_REFLECTION);
        Film direct = render(glossy, ShadingPass.DIRECT);
        Film full = render(glossy, ShadingPass.FULL);
        RGBColor background = new RGBColor(0.2, 0.5, 0.9);
        int checked = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                if (isBackground(x, y)) {
                    continue;
                }
                // the glossy term of the full image, per unit of the (uniform) background's blue
                double weight = (full.get(x, y, 2) - direct.get(x, y, 2)) / background.b();
                double[] m = {1, 0, 1};
                for (int ch = 0; ch < 3; ch++) {
                    assertEquals(direct.get(x, y, ch) + weight * m[ch], magenta.get(x, y, ch), 1e-6, "glossy " + x + "," + y);
                }
                checked += weight > 0.01 ? 1 : 0;
            }
        }
        assertTrue(checked > 100, "the glossy rays reflected the background at only " + checked + " pixels");
    }

    @Test
    void magentaKeepsTheOtherTermsAndReplacesOnlyWhatIsReflected() {
        // a brown mirror with a highlight: magenta = direct + Schlick's fraction of (1, 0, 1)
        Material brown = new Reflective(0.2, 0.3, new RGBColor(0.5, 0.3, 0.1), 0.2, RGBColor.WHITE, 50, 0.5, RGBColor.WHITE, true);
        Film magenta = render(brown, ShadingPass.MAGENTA_REFLECTION);
        Film direct = render(brown, ShadingPass.DIRECT);
        // glass: magenta = direct + refraction + R (1, 0, 1)
        Material glass = new Dielectric(1.5, RGBColor.gray(0.2), 0.5, 100);
        Film glassMagenta = render(glass, ShadingPass.MAGENTA_REFLECTION);
        Film glassDirect = render(glass, ShadingPass.DIRECT);
        Film glassRefraction = render(glass, ShadingPass.REFRACTION);
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                if (isBackground(x, y)) {
                    continue;
                }
                double px = ((x + 0.5) / SIZE * 2 - 1) * 1.2;
                double py = (1 - (y + 0.5) / SIZE * 2) * 1.2;
                double cos = Math.sqrt(1 - px * px - py * py);
                double schlick = raytracer.math.Fresnel.schlick(0.5, cos);
                double fresnel = raytracer.math.Fresnel.dielectric(cos, 1, 1.5);
                double[] m = {1, 0, 1};
                for (int ch = 0; ch < 3; ch++) {
                    assertEquals(direct.get(x, y, ch) + schlick * m[ch], magenta.get(x, y, ch), 1e-6, "mirror " + x + "," + y);
                    assertEquals(glassDirect.get(x, y, ch) + glassRefraction.get(x, y, ch) + fresnel * m[ch],
                                 glassMagenta.get(x, y, ch), 1e-6, "glass " + x + "," + y);
                }
            }
        }
    }
}
