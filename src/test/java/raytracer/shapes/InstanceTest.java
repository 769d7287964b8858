package raytracer.shapes;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raytracer.shapes.HitTesting.ray;

import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.materials.Matte;
import raytracer.math.Matrix4;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;

class InstanceTest {
    private final HitTesting h = new HitTesting();

    @Test
    void nonUniformScaleTransformsTheNormalByTheInverseTranspose() {
        // ellipsoid x^2/4 + y^2 + z^2 = 1; at (sqrt2, sqrt2/2, 0) the normal is along (x/4, y, z) ~ (1, 2, 0)
        Instance ellipsoid = new Instance(new Sphere(Point3D.ORIGIN, 1), Matrix4.scale(2, 1, 1));
        double y = Math.sqrt(2) / 2;
        ShadeRec sr = h.hit(ellipsoid, ray(5, y, 0, -1, 0, 0));
        assertNotNull(sr);
        assertEquals(5 - Math.sqrt(2), sr.t, 1e-12);
        assertEquals(Math.sqrt(2), sr.hitPoint.x, 1e-12);
        assertEquals(1 / Math.sqrt(5), sr.normal.x, 1e-12);
        assertEquals(2 / Math.sqrt(5), sr.normal.y, 1e-12);
        assertEquals(0, sr.normal.z, 1e-12);
    }

    @Test
    void rotatedAndTranslatedCylinderIsHitWhereItWasMoved() {
        // a unit cylinder lying along x (rotated about z), moved to z = -3
        Matrix4 m = Matrix4.translate(0, 0, -3).multiply(Matrix4.rotateZ(90));
        Instance lying = new Instance(new Cylinder(-1, 1, 0.5, true), m);
        ShadeRec sr = h.hit(lying, ray(0, 5, -3, 0, -1, 0));
        assertNotNull(sr);
        assertEquals(4.5, sr.t, 1e-12);
        assertEquals(1, sr.normal.y, 1e-12);
        assertNull(h.hit(lying, ray(0, 5, -2.4, 0, -1, 0)));
        assertFalse(h.shadowHit(lying, ray(0, 5, -2.4, 0, -1, 0), Double.POSITIVE_INFINITY));
        assertTrue(h.shadowHit(lying, ray(0.9, 5, -3, 0, -1, 0), 10));
    }

    @Test
    void nestedInstancesComposeAndTheInstanceMaterialWins() {
        Sphere sphere = new Sphere(Point3D.ORIGIN, 1);
        Matte inner = new Matte(0, 1, RGBColor.WHITE);
        Matte outer = new Matte(0, 1, RGBColor.BLACK);
        sphere.setMaterial(inner);
        Instance a = new Instance(sphere, Matrix4.translate(10, 0, 0));
        Instance b = new Instance(a, Matrix4.scale(2, 2, 2));
        b.setMaterial(outer);
        // sphere of radius 2 centred at (20, 0, 0)
        ShadeRec sr = h.hit(b, ray(20, 10, 0, 0, -1, 0));
        assertNotNull(sr);
        assertEquals(8, sr.t, 1e-12);
        assertEquals(2, sr.hitPoint.y, 1e-12);
        assertEquals(1, sr.normal.y, 1e-12);
        assertSame(outer, sr.material);
        assertTrue(b.boundingBox().contains(20, 1.9, 0));
    }

    @Test
    void raysGrazingMovedSolidsEnterBeforeTheyLeave() {
        Matrix4 m = Matrix4.translate(0.5, -1, 2).multiply(Matrix4.rotateY(30)).multiply(Matrix4.rotateX(20))
            .multiply(Matrix4.scale(2, 1, 0.5));
        double[] centre = {0.5, -1, 2};
        h.assertEntersBeforeLeaving("grazing a moved box", new Instance(new Box(new Point3D(-1, -1, -1), new Point3D(1, 1, 1)), m),
                                    centre, 8);
        h.assertEntersBeforeLeaving("grazing a moved cylinder", new Instance(new Cylinder(-1, 1, 1, true), m), centre, 8);
        h.assertEntersBeforeLeaving("grazing a moved sphere", new Instance(new Sphere(Point3D.ORIGIN, 1), m), centre, 8);
    }
}
