package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.core.Skipped;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;
import raytracer.render.RenderStats;
import raytracer.render.Renders;
import raytracer.render.SceneAnalysis;

/**
 * A thin sheet of glass against closed forms computed here apart from the renderer: the Fresnel
 * reflectance of one face from Snell's law and the amplitude coefficients, the slab's series of
 * bounces summed term by term; renders show the light going straight through, nothing lost, the
 * passes, and the same sheet from either side.
 */
class ThinDielectricTest {
    private static final double IOR = 1.5;
    /** The film holds floats: a pixel of at most 1 is within half an ulp of a float, 2^-25, of its value. */
    private static final double FLOAT = 0x1p-24;
    /** One face at normal incidence, ((n - 1) / (n + 1))^2. */
    private static final double R = 0.04;

    /** Unpolarised reflectance of one face at cos(theta_i) = c (Hecht, Optics, section 4.6). */
    private static double face(double c, double n) {
        double sinT = Math.sqrt(1 - c * c) / n;
        double cosT = Math.sqrt(1 - sinT * sinT);
        double rs = (c - n * cosT) / (c + n * cosT);
        double rp = (n * c - cosT) / (n * c + cosT);
        return (rs * rs + rp * rp) / 2;
    }

    /** The slab's reflectance, bounce by bounce: R, then T R T, T R R R T, ... until the terms vanish. */
    private static double slab(double r) {
        double t = 1 - r;
        double sum = r;
        for (double term = t * r * t; term > 1e-20; term *= r * r) {
            sum += term;
        }
        return sum;
    }

    private static Film render(String yaml) throws SceneException {
        LoadedScene scene = SceneLoader.load("sheet.yaml", yaml);
        World world = scene.world();
        world.prepare();
        Film film = new Film(world.viewPlane().hres(), world.viewPlane().vres());
        RenderStats stats = Renders.render(world, scene.rayTree(), 1, 1, film);
        assertEquals(0, stats.nonFiniteSamples());
        return film;
    }

    @Test
    void atNormalIncidenceASheetReflects2ROver1PlusR() {
        assertEquals(R, face(1, IOR), 1e-17);
        assertEquals(2 * R / (1 + R), slab(R), 1e-16);
        assertEquals(0.0769230769230769, ThinDielectric.reflectance(1, IOR), 1e-15, "2 R / (1 + R) = 2 / 26");
    }

    @Test
    void atObliqueIncidenceTheBouncesBetweenTheFacesAddUp() {
        for (double degrees : new double[] {10, 30, 45, 60, 75, 85, 89.9}) {
            double c = Math.cos(Math.toRadians(degrees));
            double expected = slab(face(c, IOR));
            double reflected = ThinDielectric.reflectance(c, IOR);
            assertEquals(expected, reflected, 1e-13, degrees + " degrees");
            assertTrue(reflected > 0 && reflected < 1, degrees + " degrees");
        }
        assertEquals(1, ThinDielectric.reflectance(0, IOR), 0, "at grazing incidence all is reflected");
        assertEquals(0, ThinDielectric.reflectance(0.5, 1), 0, "index 1 is no glass at all");
    }

    /** A sheet filling the view of an orthographic camera, tilted so that cos(theta_i) = NORMAL[2], before a white background. */
    private static String whiteWorld(String normal, String pass) {
        return "image: {width: 4, height: 4, samples: 1, sampler: regular, max-depth: 2}\n"
               + "pass: " + pass + "\nbackground: [1, 1, 1]\nambient: {radiance: 0}\n"
               + "camera: {type: orthographic, eye: [0, 0, 5], look-at: [0, 0, 0], view-height: 2}\n"
               + "materials:\n  sheet: {type: thin-dielectric, ior: 1.5}\n"
               + "objects:\n  - {type: plane, point: [0, 0, 0], normal: " + normal + ", material: sheet}\n";
    }

    private static void assertEveryPixel(Film film, double expected, String what) {
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(expected, film.get(x, y, c), FLOAT, what + ", pixel " + x + ", " + y);
                }
            }
        }
    }

    @Test
    void inAWhiteWorldTheReflectedAndTheTransmittedPartsMakeUpAllTheLight() throws SceneException {
        double half = Math.sqrt(0.75);
        String[] normals = {"[0, 0, 1]", "[0, 0, -1]", "[0, " + half + ", 0.5]", "[0, " + -half + ", -0.5]"};
        double[] cosines = {1, 1, 0.5, 0.5};
        for (int i = 0; i < normals.length; i++) {
            double reflected = slab(face(cosines[i], IOR));
            assertEveryPixel(render(whiteWorld(normals[i], "full")), 1, "normal " + normals[i] + ": R' + T' = 1");
            assertEveryPixel(render(whiteWorld(normals[i], "refraction")), 1 - reflected, "normal " + normals[i] + ": T'");
            assertEveryPixel(render(whiteWorld(normals[i], "reflection")), reflected, "normal " + normals[i] + ": R'");
        }
    }

    /**
     * A blue sphere lit by ambient light alone, seen by an orthographic camera through a sheet tilted
     * 60 degrees from the view; the mirror rays leave upwards into the black background.
     */
    private static String throughASheet(String sheet, String cutoff, String pass) {
        return "image: {width: 9, height: 9, samples: 1, sampler: regular, max-depth: 4, cutoff: " + cutoff + "}\n"
               + "pass: " + pass + "\nbackground: [0, 0, 0]\nambient: {radiance: 1}\n"
               + "camera: {type: orthographic, eye: [0, 0, 5], look-at: [0, 0, 0], view-height: 2}\n"
               + "materials:\n  sheet: {type: thin-dielectric, ior: 1.5}\n"
               + "  paint: {type: matte, ka: 1, kd: 0, color: [0.2, 0.6, 1]}\n"
               + "objects:\n  - {type: sphere, center: [0.2, -0.1, -3], radius: 0.6, material: paint}\n" + sheet;
    }

    private static final String TILTED = "  - {type: plane, point: [0, 0, 0], normal: [0, " + Math.sqrt(0.75) + ", 0.5], material: sheet}\n";

    @Test
    void lightGoesStraightThroughASheetAndThePassesAndTheCutoffSeeItsTwoParts() throws SceneException {
        Film without = render(throughASheet("", "0", "full"));
        Film with = render(throughASheet(TILTED, "0", "full"));
        Film magenta = render(throughASheet(TILTED, "0", "magenta-reflection"));
        Film pruned = render(throughASheet(TILTED, "0.2", "magenta-reflection"));
        Film direct = render(throughASheet(TILTED, "0", "direct"));
        double reflected = slab(face(0.5, IOR));
        int behind = 0;
        for (int y = 0; y < 9; y++) {
            for (int x = 0; x < 9; x++) {
                behind += without.get(x, y, 2) > 0 ? 1 : 0;
                for (int c = 0; c < 3; c++) {
                    double seen = without.get(x, y, c);
                    String at = "pixel " + x + ", " + y + ", channel " + c;
                    // not bent, not moved: every pixel is what it was, times T'
                    assertEquals((1 - reflected) * seen, with.get(x, y, c), FLOAT, at);
                    // the mirror rays of the magenta pass see magenta, weighted R'
                    assertEquals((1 - reflected) * seen + reflected * (c == 1 ? 0 : 1), magenta.get(x, y, c), FLOAT, at);
                    // R' = 0.164 is below the cutoff: no mirror ray is traced
                    assertEquals((1 - reflected) * seen, pruned.get(x, y, c), FLOAT, at);
                    // glass without a highlight has no direct light of its own
                    assertEquals(0, direct.get(x, y, c), 0, at);
                }
            }
        }
        assertTrue(behind > 10 && behind < 81, behind + " pixels see the sphere");
    }

    /**
     * A glass quad tilted 45 degrees under an orthographic camera: the light passing straight on
     * comes from a blue wall behind, the mirror direction is straight up, to a red ceiling.
     * {@code corners} lists the quad's two triangles, wound either way.
     */
    private static String quad(String glass, String corners) {
        return "image: {width: 15, height: 15, samples: 1, sampler: regular, max-depth: 4}\n"
               + "background: [0, 0, 0]\nambient: {radiance: 1}\n"
               + "camera: {type: orthographic, eye: [0, 0, 5], look-at: [0, 0, 0], view-height: 3}\n"
               + "materials:\n  glass: " + glass + "\n"
               + "  blue: {type: matte, ka: 1, kd: 0, color: [0.1, 0.2, 0.9]}\n"
               + "  red: {type: matte, ka: 1, kd: 0, color: [0.9, 0.2, 0.1]}\n"
               + "objects:\n  - {type: plane, point: [0, 0, -5], normal: [0, 0, 1], material: blue}\n"
               + "  - {type: plane, point: [0, 5, 0], normal: [0, -1, 0], material: red}\n" + corners;
    }

    /** The quad y + z = 0 for |x| <= 1, |y| <= 0.7: its triangles face the camera (normal (0, 1, 1)) or away. */
    private static String corners(boolean facingTheCamera) {
        String a = "[-1, -0.7, 0.7]";
        String b = "[1, -0.7, 0.7]";
        String c = "[1, 0.7, -0.7]";
        String d = "[-1, 0.7, -0.7]";
        return facingTheCamera
            ? "  - {type: triangle, vertices: [" + a + ", " + b + ", " + c + "], material: glass}\n"
              + "  - {type: triangle, vertices: [" + a + ", " + c + ", " + d + "], material: glass}\n"
            : "  - {type: triangle, vertices: [" + a + ", " + c + ", " + b + "], material: glass}\n"
              + "  - {type: triangle, vertices: [" + a + ", " + d + ", " + c + "], material: glass}\n";
    }

    @Test
    void aGlassQuadLooksTheSameFromEitherSide() throws SceneException {
        String thin = "{type: thin-dielectric, ior: 1.5}";
        Film front = render(quad(thin, corners(true)));
        Film back = render(quad(thin, corners(false)));
        double reflected = slab(face(Math.sqrt(0.5), IOR));
        double[] blue = {0.1, 0.2, 0.9};
        double[] red = {0.9, 0.2, 0.1};
        int onTheQuad = 0;
        for (int y = 0; y < 15; y++) {
            for (int x = 0; x < 15; x++) {
                // pixel centres at -1.4 + 0.2 i; the quad spans |x| <= 1 and, seen from above, |y| <= 0.7
                double px = -1.4 + 0.2 * x;
                double py = 1.4 - 0.2 * y;
                boolean inside = Math.abs(px) < 0.95 && Math.abs(py) < 0.65;
                onTheQuad += inside ? 1 : 0;
                for (int c = 0; c < 3; c++) {
                    String at = "pixel " + x + ", " + y + ", channel " + c;
                    assertEquals(front.get(x, y, c), back.get(x, y, c), FLOAT, at);
                    if (inside) {
                        assertEquals((1 - reflected) * blue[c] + reflected * red[c], front.get(x, y, c), FLOAT, at);
                    }
                }
            }
        }
        assertEquals(63, onTheQuad);
        // a solid dielectric quad is the inside of a medium from behind: at 45 degrees it reflects all
        String solid = "{type: dielectric, ior: 1.5}";
        Film solidBack = render(quad(solid, corners(false)));
        for (int c = 0; c < 3; c++) {
            assertEquals(red[c], solidBack.get(7, 7, c), FLOAT, "total internal reflection from behind");
        }
    }

    /**
     * The scene analysis asks the sheet what it needs, as it asks a Dielectric: a sheet without a
     * highlight evaluates no light (its samples are counted as skipped, not traced), and the image
     * is the same to the bit.
     */
    @Test
    void theSceneAnalysisLeavesOutTheLightsOfASheetWithoutAHighlightAndChangesNoPixel() throws SceneException {
        String yaml = throughASheet(TILTED, "0", "full").replace("ambient: {radiance: 1}\n",
            "ambient: {radiance: 1}\nlights:\n  - {type: point, position: [0, 4, 3], intensity: 20}\n");
        LoadedScene plain = SceneLoader.load("sheet.yaml", yaml);
        LoadedScene analysed = SceneLoader.load("sheet.yaml", yaml);
        SceneAnalysis analysis = SceneAnalysis.apply(analysed.world(), analysed.rayTree());
        assertTrue(analysis.skips().stream().anyMatch(k -> k.counter() == Skipped.LIGHT_SAMPLES && k.why().contains("'sheet'")),
                   analysis.skips().toString());
        Film[] films = new Film[2];
        RenderStats[] stats = new RenderStats[2];
        LoadedScene[] scenes = {plain, analysed};
        for (int i = 0; i < 2; i++) {
            World world = scenes[i].world();
            world.prepare();
            films[i] = new Film(9, 9);
            stats[i] = Renders.render(world, scenes[i].rayTree(), 1, 1, films[i]);
        }
        for (int y = 0; y < 9; y++) {
            for (int x = 0; x < 9; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(films[0].get(x, y, c), films[1].get(x, y, c), 0, "pixel " + x + ", " + y);
                }
            }
        }
        assertTrue(stats[1].skipped(Skipped.LIGHT_SAMPLES) >= 81, "a light sample left out at each of the sheet's hits");
        assertEquals(0, stats[0].skipped(Skipped.LIGHT_SAMPLES));
    }
}
