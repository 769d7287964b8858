package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Pinhole;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.core.Skipped;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.materials.Matte;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Vector3D;
import raytracer.samplers.Regular;
import raytracer.textures.Checker;
import raytracer.textures.ConstantColor;

/**
 * A sphere's u, v cost an atan2 and an acos: the materials and instances say whether shading may
 * read them (a texture that is not a constant colour); a sphere leaves them out, and counts it, only
 * when the world says none is read (the scene analysis decides that), and else computes them exactly.
 */
class TextureCoordinatesTest {

    private static Matte plain() {
        return new Matte(0.2, 0.8, RGBColor.WHITE);
    }

    private static Matte textured() {
        Matte m = plain();
        m.setTexture(new Checker(RGBColor.WHITE, RGBColor.BLACK, 0.1));
        return m;
    }

    private static World prepared(GeometricObject... objects) {
        World world = new World(new ViewPlane(4, 4, 1, new Regular(), 1, 1),
                                new Pinhole(new Point3D(0, 0, 5), Point3D.ORIGIN, Vector3D.UP, 40), new Ambient(0, RGBColor.WHITE));
        for (GeometricObject o : objects) {
            world.addObject(o);
        }
        world.prepare();
        return world;
    }

    private static Sphere sphere(raytracer.core.Material m) {
        Sphere s = new Sphere(Point3D.ORIGIN, 1);
        s.setMaterial(m);
        return s;
    }

    @Test
    void objectsSayWhetherTheirShadingReadsUv() {
        assertFalse(sphere(plain()).usesTextureCoordinates(), "a plain colour");
        Matte constant = plain();
        constant.setTexture(new ConstantColor(RGBColor.WHITE));
        assertFalse(sphere(constant).usesTextureCoordinates(), "a constant texture reads no u, v");
        assertTrue(sphere(textured()).usesTextureCoordinates(), "a checker");
        Instance over = new Instance(sphere(plain()), Matrix4.translate(1, 0, 0));
        over.setMaterial(textured());
        assertTrue(over.usesTextureCoordinates(), "the instance's textured material covers a plain sphere");
        Instance under = new Instance(sphere(textured()), Matrix4.translate(1, 0, 0));
        under.setMaterial(plain());
        assertFalse(under.usesTextureCoordinates(), "the instance's plain material replaces a textured one");
        assertTrue(new Instance(sphere(textured()), Matrix4.translate(1, 0, 0)).usesTextureCoordinates());
        assertTrue(new Sphere(Point3D.ORIGIN, 1).usesTextureCoordinates(), "without a material, assume so");
    }

    @Test
    void uvAreComputedOnlyWhenNeededAndThenExactly() {
        for (boolean textured : new boolean[] {false, true}) {
            World world = prepared(sphere(textured ? textured() : plain()));
            if (!textured) {
                world.leaveOutTextureCoordinates(); // as the scene analysis decides
            }
            ShadeRec sr = new WorkerScratch(world).shadeRec(0);
            // a ray hitting the sphere at (sin 30, 0, cos 30): u = (atan2(x, z) + pi) / 2 pi, v = 1/2
            Ray ray = new Ray().set(0.5, 0, 5, 0, 0, -1);
            assertTrue(world.hit(ray, sr));
            assertEquals(textured ? (Math.PI / 6 + Math.PI) / (2 * Math.PI) : 0, sr.u, 1e-12, "u, textured " + textured);
            assertEquals(textured ? 0.5 : 0, sr.v, 1e-12, "v, textured " + textured);
            assertEquals(textured ? 0 : 1, sr.scratch.skipped[Skipped.TEXTURE_COORDINATES], "counted when left out");
        }
    }
}
