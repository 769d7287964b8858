package raytracer.io.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import raytracer.cache.MeshCache;
import raytracer.cameras.Pinhole;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.io.obj.ObjLoader;
import raytracer.io.obj.ObjMaterial;
import raytracer.lights.Ambient;
import raytracer.materials.Dielectric;
import raytracer.materials.Emissive;
import raytracer.materials.Matte;
import raytracer.materials.Phong;
import raytracer.materials.ThinDielectric;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;
import raytracer.math.Vector3D;

/** How the keys of an MTL file become our materials. */
class MeshReaderTest {

    @Test
    void mtlKeysChooseTheMaterial(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("m.mtl"), String.join("\n",
            "newmtl chalk", "Kd 0.5 0.6 0.7",
            "newmtl plastic", "Kd 0.2 0.2 0.8", "Ks 0.5 0.5 0.5", "Ns 60",
            "newmtl window", "Kd 1 1 1", "d 0.2", "Ni 1",
            "newmtl water", "Tr 0.9", "Ni 1.33",
            "newmtl lamp", "Kd 1 1 1", "Ke 4 3 2",
            "newmtl unlit-shine", "Ks 1 1 1",
            "newmtl opaque-tr", "Tr 0",
            "newmtl d-wins", "d 1", "Tr 0.9", ""));
        StringBuilder obj = new StringBuilder("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
        for (String name : List.of("chalk", "plastic", "window", "water", "lamp", "unlit-shine", "opaque-tr", "d-wins")) {
            obj.append("usemtl ").append(name).append("\nf 1 2 3\n"); // the loader keeps the materials faces use
        }
        Files.writeString(dir.resolve("m.obj"), obj);
        List<ObjMaterial> mtl = ObjLoader.load(dir.resolve("m.obj"), false).materials();
        World world = world();
        LoadReport report = new LoadReport();
        TextureReader textures = new TextureReader(new Source(dir.resolve("s.yaml").toString(), dir));
        Material[] m = new Material[mtl.size()];
        for (int i = 0; i < m.length; i++) {
            m[i] = MeshReader.fromMtl(mtl.get(i), false, textures, report);
        }
        assertEquals(8, m.length, mtl.toString());
        assertInstanceOf(Matte.class, m[0]);
        assertInstanceOf(Phong.class, m[1], "Ks with Ns adds a Phong lobe");
        assertEquals(1.5, assertInstanceOf(Dielectric.class, m[2]).ior(), 0, "d < 1 with the exporters' default Ni 1 is glass");
        assertEquals(1.33, assertInstanceOf(Dielectric.class, m[3]).ior(), 0, "Tr is 1 - d");
        assertInstanceOf(Emissive.class, m[4]);
        assertInstanceOf(Matte.class, m[5], "Ks without Ns has no lobe to shape");
        assertInstanceOf(Matte.class, m[6], "Tr 0 is opaque");
        assertInstanceOf(Matte.class, m[7], "d wins over Tr, whatever their order");

        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        MutableRgb out = new MutableRgb();
        sr.frontFace = true;
        m[4].shade(sr, out);
        assertEquals(4, out.r, 0);
        assertEquals(3, out.g, 0);
        assertEquals(2, out.b, 0);
        sr.frontFace = false;
        m[4].shade(sr, out);
        assertEquals(0, out.r + out.g + out.b, 0, "an emitter is dark from behind");
        assertEquals(2, report.warnings().size(), "each glass reading is announced: " + report.warnings());
        assertTrue(report.warnings().get(0).contains("'window'") && report.warnings().get(0).contains("glass of index 1.5"),
                   report.warnings().get(0));
    }

    @Test
    void kdAndKsReachTheShading(@TempDir Path dir) throws Exception {
        // a quad facing +z lit by a point light of intensity 1 at the eye, 1 unit away, no ambient:
        // the centre receives irradiance 1 and sees the light's mirror direction, so it shows
        // Kd / pi (Lambert) plus Ks (the unnormalised Phong lobe at its peak)
        Files.writeString(dir.resolve("m.mtl"), String.join("\n",
            "newmtl chalk", "Kd 0.5 0.6 0.7",
            "newmtl plastic", "Kd 0.2 0.3 0.8", "Ks 0.5 0.25 0.125", "Ns 60", ""));
        double[][] expected = {
            {0.5 / Math.PI, 0.6 / Math.PI, 0.7 / Math.PI},
            {0.2 / Math.PI + 0.5, 0.3 / Math.PI + 0.25, 0.8 / Math.PI + 0.125},
        };
        String[] names = {"chalk", "plastic"};
        for (int i = 0; i < 2; i++) {
            Files.writeString(dir.resolve("quad.obj"), "mtllib m.mtl\nusemtl " + names[i]
                + "\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
            Files.writeString(dir.resolve("s.yaml"), "ambient: {radiance: 0}\n"
                + "lights: [{type: point, position: [0.1, 0.2, 1], intensity: 1}]\nobjects:\n  - {type: mesh, file: quad.obj}\n");
            World world = SceneLoader.load(dir.resolve("s.yaml")).world();
            world.prepare();
            ShadeRec sr = new WorkerScratch(world).shadeRec(0);
            assertTrue(world.hit(new Ray().set(0.1, 0.2, 1, 0, 0, -1), sr));
            MutableRgb out = new MutableRgb();
            sr.material.shade(sr, out);
            assertEquals(expected[i][0], out.r, 1e-12, names[i]);
            assertEquals(expected[i][1], out.g, 1e-12, names[i]);
            assertEquals(expected[i][2], out.b, 1e-12, names[i]);
        }
    }

    @Test
    void normalMapKeysOfAMeshObject(@TempDir Path dir) throws Exception {
        // a quad in z = 0 facing +z, with UVs, and a uniform object-space map encoding (0.6, 0, 0.8)
        Files.writeString(dir.resolve("quad.obj"),
            "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
        BufferedImage map = new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB);
        for (int k = 0; k < 4; k++) {
            map.setRGB(k % 2, k / 2, (204 << 16) | (128 << 8) | 230);
        }
        ImageIO.write(map, "png", dir.resolve("n.png").toFile());
        MutableVec3 mapped = normalAtCentre(dir, "normal-map: {file: n.png, space: object}");
        assertEquals(2 * 204 / 255.0 - 1, mapped.x, 0.01);
        assertEquals(0, mapped.y, 0.01);
        assertEquals(2 * 230 / 255.0 - 1, mapped.z, 0.01);
        MutableVec3 tangent = normalAtCentre(dir, "normal-map: {file: n.png, space: tangent}");
        // with u along +x and v along +y the tangent frame is the object frame here
        assertEquals(mapped.x, tangent.x, 1e-6);
        assertEquals(mapped.z, tangent.z, 1e-6);

        // the same quad with an MTL whose norm map is the same picture: read as tangent space
        Files.writeString(dir.resolve("quad.mtl"), "newmtl bumpy\nKd 0.5 0.5 0.5\nnorm n.png\n");
        Files.writeString(dir.resolve("quad.obj"), "mtllib quad.mtl\nusemtl bumpy\n" + Files.readString(dir.resolve("quad.obj")));
        MutableVec3 fromMtl = normalAtCentre(dir, "smooth: false");
        assertEquals(mapped.x, fromMtl.x, 1e-6, "the MTL's norm map applies without a normal-map key");
        MutableVec3 plain = normalAtCentre(dir, "normal-map: none");
        assertEquals(1, plain.z, 1e-12, "none: not even the MTL's map, the face normal");

        String[][] bad = {
            {"normal-map: {file: n.png, space: world}", "unknown normal-map space 'world'; allowed: object, tangent"},
            {"normal-map: yes", "'normal-map' is {file, space} or none"},
            {"normal-map: {file: gone.png}", "gone.png"},
            {"normal-map: {file: n.png, scale: 2}", "'scale'"},
        };
        for (String[] b : bad) {
            Files.writeString(dir.resolve("bad.yaml"), "objects:\n  - {type: mesh, file: quad.obj, " + b[0] + "}\n");
            SceneException e = assertThrows(SceneException.class, () -> SceneLoader.load(dir.resolve("bad.yaml")), b[0]);
            assertTrue(e.getMessage().startsWith(dir.resolve("bad.yaml") + ":2:"), e.getMessage());
            assertTrue(e.getMessage().contains(b[1]), b[1] + " missing from: " + e.getMessage());
        }
    }

    /**
     * Glass from an MTL file is a thin sheet where its triangles leave an edge open (a window pane
     * is no inside of a medium from behind) and a solid where they close; the choice is the same
     * when the mesh comes back from the mesh cache, which stores it.
     */
    @Test
    void anOpenGlassSheetIsThinGlassAndAClosedGlassMeshIsASolid(@TempDir Path dir) throws Exception {
        Files.writeString(dir.resolve("m.mtl"), "newmtl bottle\nd 0.1\nNi 1.5\nnewmtl window\nd 0.2\nNi 1.5\n");
        StringBuilder obj = new StringBuilder("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n"
                                              + "v 1 1 1\nv 0 1 1\nv 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 1 0\nusemtl bottle\n");
        for (String face : new String[] {"1 4 3 2", "5 6 7 8", "1 2 6 5", "2 3 7 6", "3 4 8 7", "4 1 5 8"}) {
            obj.append("f ").append(face).append('\n');
        }
        obj.append("usemtl window\nf 9 10 11 12\n");
        Files.writeString(dir.resolve("m.obj"), obj);
        Path scene = Files.writeString(dir.resolve("s.yaml"), "objects:\n  - {type: mesh, file: m.obj}\n");
        MeshCache cache = MeshCache.in(dir.resolve("cache"), Long.MAX_VALUE, 0);
        for (String load : new String[] {"parsed", "read from the mesh cache"}) {
            LoadedScene loaded = SceneLoader.load(scene, cache);
            loaded.world().prepare();
            boolean fromCache = loaded.report().statistics().stream().anyMatch(line -> line.contains("read from the mesh cache"));
            assertEquals(load.equals("read from the mesh cache"), fromCache, load + ": " + loaded.report().statistics());
            List<Material> materials = loaded.world().materials();
            Material bottle = materials.stream().filter(m -> m.name().equals("bottle")).findFirst().orElseThrow();
            Material window = materials.stream().filter(m -> m.name().equals("window")).findFirst().orElseThrow();
            assertInstanceOf(Dielectric.class, bottle, load + ": the closed cube is a solid");
            assertEquals(1.5, assertInstanceOf(ThinDielectric.class, window, load + ": the open quad is a sheet").ior(), 0);
            assertTrue(loaded.report().warnings().stream().anyMatch(w -> w.contains("'window'") && w.contains("thin sheet")),
                       loaded.report().warnings().toString());
        }
    }

    /** The shading normal where a ray from +z meets the quad of {@code quad.obj} under these keys. */
    private static MutableVec3 normalAtCentre(Path dir, String keys) throws Exception {
        Files.writeString(dir.resolve("s.yaml"), "objects:\n  - {type: mesh, file: quad.obj, " + keys + "}\n");
        World world = SceneLoader.load(dir.resolve("s.yaml")).world();
        world.prepare();
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        assertTrue(world.hit(new Ray().set(0.1, 0.2, 3, 0, 0, -1), sr));
        return new MutableVec3().set(sr.normal);
    }

    private static World world() {
        return new World(new ViewPlane(1, 1, 1, (n, rng, xs, ys) -> { }, 2, 1),
            new Pinhole(new Point3D(0, 0, 1), Point3D.ORIGIN, Vector3D.UP, 45), new Ambient(0, RGBColor.WHITE));
    }
}
