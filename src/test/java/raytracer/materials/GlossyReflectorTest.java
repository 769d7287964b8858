package raytracer.materials;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.Renders;
import raytracer.samplers.PureRandom;
import raytracer.shapes.Plane;
import raytracer.tracers.Whitted;

/**
 * A glossy floor under an emitting ceiling and nothing else: no light is sampled, so all it shows
 * is what its glossy rays find. Seen straight from above, the mirror direction is the normal and
 * E[f cos / pdf] = ks 2 pi / (e + 1) E[cos alpha] = ks 2 pi / (e + 2) for the report's cos^e lobe.
 */
class GlossyReflectorTest {
    private static final int SIZE = 24;
    private static final double KS = 0.6;
    private static final double EXP = 10;
    private static final double LS = 2;
    private static final RGBColor GLOW = new RGBColor(1, 0.5, 0.25);
    private static final RGBColor CS = new RGBColor(0.9, 0.8, 0.7);

    private static Film render(boolean ceilingFacesDown) {
        World world = new World(new ViewPlane(SIZE, SIZE, 1, new PureRandom(), 2, 1),
            new Orthographic(new Point3D(0, 0.5, 0), Point3D.ORIGIN, new Vector3D(0, 0, 1), 4), new Ambient(0, RGBColor.WHITE));
        Plane floor = new Plane(Point3D.ORIGIN, new Normal(0, 1, 0));
        floor.setMaterial(new GlossyReflector(0, 0, RGBColor.BLACK, KS, CS, EXP, 64, false));
        Plane ceiling = new Plane(new Point3D(0, 1, 0), new Normal(0, ceilingFacesDown ? -1 : 1, 0));
        ceiling.setMaterial(new Emissive(LS, GLOW));
        world.addObject(floor);
        world.addObject(ceiling);
        world.setTracer(Whitted::new);
        world.prepare();
        Film film = new Film(SIZE, SIZE);
        Renders.render(world, 2, 7, film);
        return film;
    }

    @Test
    void glossyRaysThatHitAnEmitterBringBackItsRadiance() {
        Film film = render(true);
        double[] sum = new double[3];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                for (int c = 0; c < 3; c++) {
                    sum[c] += film.get(x, y, c);
                }
            }
        }
        double lobe = KS * 2 * Math.PI / (EXP + 2);
        double[] expected = {lobe * CS.r() * LS * GLOW.r(), lobe * CS.g() * LS * GLOW.g(), lobe * CS.b() * LS * GLOW.b()};
        for (int c = 0; c < 3; c++) {
            // 36,864 glossy rays; the per-ray weight, proportional to cos(alpha), has a standard
            // deviation of 8% for e = 10, so the mean is good to 0.05%
            assertEquals(expected[c], sum[c] / (SIZE * SIZE), 0.003 * expected[c], "channel " + c);
        }
    }

    @Test
    void anEmitterSeenFromBehindIsDark() {
        Film film = render(false);
        double max = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                max = Math.max(max, film.get(x, y, 0) + film.get(x, y, 1) + film.get(x, y, 2));
            }
        }
        assertTrue(max == 0, "emits only from its front side: " + max);
    }
}
