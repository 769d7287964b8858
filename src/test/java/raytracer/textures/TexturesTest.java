package raytracer.textures;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Pinhole;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.Vector3D;

class TexturesTest {

    /** An 8 x 4 image whose red channel is the column index and green the row index. */
    private static Film ramp() {
        Film film = new Film(8, 4);
        for (int y = 0; y < 4; y++) {
            for (int x = 0; x < 8; x++) {
                film.set(x, y, x, y, 1);
            }
        }
        return film;
    }

    private static MutableRgb look(EnvironmentMap map, double dx, double dy, double dz) {
        MutableRgb out = new MutableRgb();
        map.radiance(new Ray().set(0, 0, 0, dx, dy, dz), out);
        return out;
    }

    @Test
    void axisDirectionsLookUpTheRightTexels() {
        EnvironmentMap map = new EnvironmentMap(ramp(), 1);
        // -z: the image centre, u = 1/2, v = 1/2: between columns 3 and 4 and rows 1 and 2
        assertEquals(3.5, look(map, 0, 0, -1).r, 1e-12);
        assertEquals(1.5, look(map, 0, 0, -1).g, 1e-12);
        // +x a quarter turn right (u = 3/4), -x a quarter left (u = 1/4)
        assertEquals(5.5, look(map, 1, 0, 0).r, 1e-12);
        assertEquals(1.5, look(map, -1, 0, 0).r, 1e-12);
        // +z is the seam, u = 0 = 1: halfway between the last and first columns
        assertEquals(3.5, look(map, 0, 0, 1).r, 1e-12);
        // straight up is the top row, straight down the bottom row (no wrapping at the poles)
        assertEquals(0, look(map, 0, 1, 0).g, 1e-12);
        assertEquals(3, look(map, 0, -1, 0).g, 1e-12);
        // direction length does not matter, intensity scales
        assertEquals(2 * 5.5, look(new EnvironmentMap(ramp(), 2), 7, 0, 0).r, 1e-12);
        // turned 90 degrees about +y, the image centre is seen down -x and +x sees the seam
        EnvironmentMap turned = new EnvironmentMap(ramp(), 1, 90);
        assertEquals(3.5, look(turned, -1, 0, 0).r, 1e-12);
        assertEquals(1.5, look(turned, -1, 0, 0).g, 1e-12);
        assertEquals(3.5, look(turned, 1, 0, 0).r, 1e-12);
        assertEquals(5.5, look(turned, 0, 0, -1).r, 1e-12);
        assertEquals(look(map, 0.3, 0.2, -0.9).r, look(new EnvironmentMap(ramp(), 1, 360), 0.3, 0.2, -0.9).r, 1e-12);
    }

    @Test
    void checkerAndImageTexturesFollowUv() {
        World world = new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 1, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        Checker checker = new Checker(RGBColor.WHITE, RGBColor.BLACK, 0.25);
        MutableRgb out = new MutableRgb();
        double[][] uvs = {{0.1, 0.1}, {0.3, 0.1}, {0.3, 0.3}, {-0.1, 0.1}};
        double[] expected = {1, 0, 1, 0};
        for (int i = 0; i < uvs.length; i++) {
            sr.u = uvs[i][0];
            sr.v = uvs[i][1];
            checker.getColor(sr, out);
            assertEquals(expected[i], out.r, 0, "uv " + uvs[i][0] + ", " + uvs[i][1]);
        }
        ImageTexture image = new ImageTexture(ramp());
        // v runs up the image: v near 1 is the top row (0), near 0 the bottom row (3)
        sr.u = 2.5 / 8;
        sr.v = 1 - 0.5 / 4;
        image.getColor(sr, out);
        assertEquals(2, out.r, 1e-12);
        assertEquals(0, out.g, 1e-12);
        sr.v = 0.5 / 4;
        image.getColor(sr, out);
        assertEquals(3, out.g, 1e-12);
    }
}
