package raytracer.shapes.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.util.List;
import org.junit.jupiter.api.Test;
import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.Ray;

/** Normal maps on a square in the z = 0 plane whose u runs along +x and v along +y. */
class NormalMapTest {

    private static TriangleMesh square() {
        double[] p = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
        float[] uv = {0, 0, 1, 0, 1, 1, 0, 1};
        float[] n = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
        return new TriangleMesh(new Mesh(p, n, uv, new int[] {0, 1, 2, 0, 2, 3}, null), List.of());
    }

    /** A map of one colour everywhere. */
    private static Texture constant(double r, double g, double b) {
        return (sr, out) -> out.set(r, g, b);
    }

    private static ShadeRec shoot(TriangleMesh mesh) {
        ShadeRec sr = MeshTesting.shadeRec();
        Ray ray = new Ray().set(0.3, 0.6, 5, 0, 0, -1);
        sr.beginSearch(ray, 0, Double.POSITIVE_INFINITY);
        assertNotNull(mesh.hit(ray, sr) ? sr : null);
        sr.complete(ray);
        return sr;
    }

    @Test
    void aFlatTangentSpaceMapChangesNothing() {
        TriangleMesh plain = square();
        TriangleMesh mapped = square();
        mapped.setNormalMap(0, constant(0.5, 0.5, 1), true);
        ShadeRec a = shoot(plain);
        double nx = a.normal.x;
        double ny = a.normal.y;
        double nz = a.normal.z;
        ShadeRec b = shoot(mapped);
        assertEquals(nx, b.normal.x, 1e-12);
        assertEquals(ny, b.normal.y, 1e-12);
        assertEquals(nz, b.normal.z, 1e-12);
    }

    @Test
    void aTiltedTangentSpaceMapLeansTheNormalAlongU() {
        // tangent-space normal (sin 30, 0, cos 30): towards +u, which is +x on this square
        double s = 0.5;
        double c = Math.sqrt(3) / 2;
        TriangleMesh mapped = square();
        mapped.setNormalMap(0, constant((s + 1) / 2, 0.5, (c + 1) / 2), true);
        ShadeRec sr = shoot(mapped);
        assertEquals(s, sr.normal.x, 1e-9);
        assertEquals(0, sr.normal.y, 1e-9);
        assertEquals(c, sr.normal.z, 1e-9);
        // green is +v, so +y here (OpenGL convention)
        TriangleMesh up = square();
        up.setNormalMap(0, constant(0.5, (s + 1) / 2, (c + 1) / 2), true);
        assertEquals(s, shoot(up).normal.y, 1e-9);
    }

    @Test
    void anObjectSpaceMapGivesTheNormalDirectly() {
        TriangleMesh mapped = square();
        // object-space (0.6, 0, 0.8)
        mapped.setNormalMap(0, constant(0.8, 0.5, 0.9), false);
        ShadeRec sr = shoot(mapped);
        assertEquals(0.6, sr.normal.x, 1e-9);
        assertEquals(0, sr.normal.y, 1e-9);
        assertEquals(0.8, sr.normal.z, 1e-9);
        // every component in its own channel: (2, -3, 6) / 7, with green the y axis and its sign kept
        TriangleMesh tilted = square();
        tilted.setNormalMap(0, constant((2 / 7.0 + 1) / 2, (-3 / 7.0 + 1) / 2, (6 / 7.0 + 1) / 2), false);
        ShadeRec t = shoot(tilted);
        assertEquals(2 / 7.0, t.normal.x, 1e-9);
        assertEquals(-3 / 7.0, t.normal.y, 1e-9);
        assertEquals(6 / 7.0, t.normal.z, 1e-9);
    }
}
