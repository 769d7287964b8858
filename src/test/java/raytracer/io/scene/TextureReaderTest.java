package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.StringReader;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.yaml.snakeyaml.Yaml;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.cameras.Pinhole;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;
import raytracer.math.Vector3D;
import raytracer.textures.ConstantColor;
import raytracer.textures.ImageTexture;

/** Texture entries of a scene file: each type, and the errors a user can make. */
class TextureReaderTest {

    private static Node node(String yaml) {
        return new Yaml().compose(new StringReader(yaml));
    }

    /** The sRGB transfer function's inverse (IEC 61966-2-1), written out independently here. */
    private static double linear(int code) {
        double c = code / 255.0;
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    @Test
    void eachTextureType(@TempDir Path dir) throws Exception {
        BufferedImage png = new BufferedImage(2, 1, BufferedImage.TYPE_INT_RGB);
        png.setRGB(0, 0, (255 << 16) | (128 << 8) | 10);
        png.setRGB(1, 0, (0 << 16) | (64 << 8) | 200);
        ImageIO.write(png, "png", dir.resolve("t.png").toFile());
        TextureReader reader = new TextureReader(new Source(dir.resolve("s.yaml").toString(), dir));

        Texture image = reader.texture(node("{type: image, file: t.png}"));
        assertInstanceOf(ImageTexture.class, image);
        Texture constant = reader.texture(node("{type: constant, color: [0.25, 0.5, 0.75]}"));
        Texture checker = reader.texture(node("{type: checker, color-a: [1, 0, 0], color-b: [0, 0, 1], size: 0.5}"));

        ShadeRec sr = new WorkerScratch(new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 2, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE))).shadeRec(0);
        MutableRgb out = new MutableRgb();
        // the left texel's centre: u = 0.25; the PNG's 8-bit sRGB codes come back as linear radiance
        sr.u = 0.25;
        sr.v = 0.5;
        image.getColor(sr, out);
        assertEquals(linear(255), out.r, 1e-6);
        assertEquals(linear(128), out.g, 1e-6);
        assertEquals(linear(10), out.b, 1e-6);
        sr.u = 0.75;
        image.getColor(sr, out);
        assertEquals(linear(64), out.g, 1e-6);
        assertEquals(linear(200), out.b, 1e-6);
        for (double u : new double[] {-3, 0.1, 7.5}) {
            sr.u = u;
            constant.getColor(sr, out);
            assertEquals(0.25, out.r, 0);
            assertEquals(0.5, out.g, 0);
            assertEquals(0.75, out.b, 0);
        }
        assertInstanceOf(ConstantColor.class, constant);
        // squares of 0.5 in u and v, colour a in the square at the origin, alternating along each axis
        double[][] cells = {{0.25, 0.25, 1, 0}, {0.75, 0.25, 0, 1}, {0.25, 0.75, 0, 1}, {0.75, 0.75, 1, 0},
                            {-0.25, 0.25, 0, 1}, {1.25, 1.25, 1, 0}, {1.25, 1.75, 0, 1}, {0.49, 0.01, 1, 0}, {0.51, 0.01, 0, 1}};
        for (double[] c : cells) {
            sr.u = c[0];
            sr.v = c[1];
            checker.getColor(sr, out);
            assertEquals(c[2], out.r, 0, "red at " + c[0] + ", " + c[1]);
            assertEquals(0, out.g, 0);
            assertEquals(c[3], out.b, 0, "blue at " + c[0] + ", " + c[1]);
        }
        Texture defaults = reader.texture(node("{type: checker}"));
        sr.u = 0.05;
        sr.v = 0.05;
        defaults.getColor(sr, out);
        assertEquals(1, out.r, 0, "color-a defaults to white");
        sr.u = 0.15;
        defaults.getColor(sr, out);
        assertEquals(0.1, out.r, 0, "color-b defaults to grey 0.1, squares of 0.1");

        SceneException missing = assertThrows(SceneException.class, () -> reader.texture(node("{type: image, file: nowhere.png}")));
        assertTrue(missing.getMessage().contains(dir.resolve("nowhere.png").toString()), missing.getMessage());
        SceneException kind = assertThrows(SceneException.class, () -> reader.texture(node("{type: marble}")));
        assertTrue(kind.getMessage().contains("unknown texture type 'marble'; allowed: checker, constant, image"), kind.getMessage());
        SceneException key = assertThrows(SceneException.class, () -> reader.texture(node("{type: constant, colour: [1, 1, 1]}")));
        assertTrue(key.getMessage().contains("'colour'") && key.getMessage().contains("color"), key.getMessage());
    }
}
