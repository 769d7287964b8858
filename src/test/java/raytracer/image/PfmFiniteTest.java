package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cameras.Pinhole;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.lights.PointLight;
import raytracer.materials.Matte;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.render.RenderStats;
import raytracer.render.Renders;
import raytracer.samplers.Regular;
import raytracer.shapes.Sphere;
import raytracer.tracers.RayCast;

/**
 * A PFM never holds Inf or NaN: values past the float range are written as the largest float of
 * their sign, NaN as 0. The file is decoded here byte by byte, not by the project's reader.
 */
class PfmFiniteTest {
    @TempDir
    Path dir;

    @Test
    void infinityAndOverflowBecomeTheLargestFloatAndNanBecomesZero() throws IOException {
        Film film = new Film(3, 2);
        film.set(0, 0, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN);
        film.set(1, 0, 1e39, 0.5, Float.MIN_VALUE);      // 1e39 is already +Inf as a float
        film.set(2, 0, 3e38, -3e38, 1e30);               // finite floats that the exposure pushes past the range
        film.set(0, 1, 0.25, 0, 1);
        float[] values = writeAndDecode(film, 10);
        float max = Float.MAX_VALUE;
        // rows from the bottom: the file holds row 1, then row 0
        float[] expected = {2.5f, 0, 10, 0, 0, 0, 0, 0, 0,
                            max, -max, 0, max, 5, Float.MIN_VALUE * 10f, max, -max, 1e31f};
        assertEquals(expected.length, values.length);
        for (int i = 0; i < values.length; i++) {
            assertTrue(Float.isFinite(values[i]), "value " + i + " is " + values[i]);
            assertEquals(expected[i], values[i], Math.ulp(expected[i]), "value " + i);
        }
    }

    /** A point light of intensity 1e308 makes finite double radiance of about 1e307, +Inf as a float. */
    @Test
    void anAbsurdlyBrightLightWritesTheLargestFloat() throws IOException {
        World world = new World(new ViewPlane(8, 6, 1, new Regular(), 1, 1),
            new Pinhole(new Point3D(0, 0, 5), Point3D.ORIGIN, Vector3D.UP, 40), new Ambient(0, RGBColor.WHITE));
        Sphere sphere = new Sphere(Point3D.ORIGIN, 1.5);
        sphere.setMaterial(new Matte(0, 0.8, RGBColor.WHITE));
        world.addObject(sphere);
        world.addLight(new PointLight(1e308, RGBColor.WHITE, new Point3D(0, 0, 5)));
        world.setTracer(RayCast::new);
        world.prepare();
        Film film = new Film(8, 6);
        RenderStats stats = Renders.render(world, 1, 1, film);
        assertEquals(0, stats.nonFiniteSamples(), "each sample is a finite double");
        assertEquals(Float.POSITIVE_INFINITY, film.get(4, 3, 0), "the film's float overflows at the sphere's centre");
        float[] values = writeAndDecode(film, 1);
        int brightest = 0;
        for (float v : values) {
            assertTrue(Float.isFinite(v), "a PFM value is " + v);
            brightest += v == Float.MAX_VALUE ? 1 : 0;
        }
        assertTrue(brightest >= 3, brightest + " values at the largest float");
    }

    private float[] writeAndDecode(Film film, double exposure) throws IOException {
        Path file = dir.resolve("image.pfm");
        ImageWriters.write(film, exposure, file);
        byte[] bytes = Files.readAllBytes(file);
        String header = "PF\n" + film.width() + " " + film.height() + "\n-1.0\n";
        assertEquals(header, new String(bytes, 0, header.length(), StandardCharsets.US_ASCII));
        ByteBuffer data = ByteBuffer.wrap(bytes, header.length(), bytes.length - header.length()).order(ByteOrder.LITTLE_ENDIAN);
        float[] values = new float[3 * film.width() * film.height()];
        for (int i = 0; i < values.length; i++) {
            values[i] = data.getFloat();
        }
        assertEquals(0, data.remaining(), "nothing after the pixels");
        return values;
    }
}
