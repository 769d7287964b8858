package raytracer.io.scene;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import raytracer.accel.FlatBVH;
import raytracer.accel.MedianSplitBuilder;
import raytracer.accel.MeshBVH;
import raytracer.accel.SahBuilder;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.Texture;
import raytracer.io.obj.ObjException;
import raytracer.io.obj.ObjLoader;
import raytracer.io.obj.ObjMaterial;
import raytracer.io.obj.ObjModel;
import raytracer.materials.Dielectric;
import raytracer.materials.Emissive;
import raytracer.materials.Matte;
import raytracer.materials.Phong;
import raytracer.math.RGBColor;
import raytracer.shapes.mesh.TriangleMesh;
import raytracer.textures.ImageTexture;

/**
 * A {@code mesh} object: an OBJ file under a BVH. Without a {@code material} key the file's MTL
 * materials are used, mapped onto ours by {@link #fromMtl}.
 */
final class MeshReader {
    /**
     * Most triangles per leaf of the median-split tree (the report's builder); leaves hold 4 to 8.
     * Against 4: one level less, half the records, and the dragon's frame rays 3-7% faster in the
     * frame-ray harness (6 and 12 measured about the same as 8).
     */
    static final int MEDIAN_LEAF_SIZE = 8;
    static final int SAH_MAX_LEAF_SIZE = 4;

    private MeshReader() {
    }

    static GeometricObject read(YamlObject o, Material override, LoadReport report, TextureReader textures) throws SceneException {
        Path file = o.source().resolve(o.requiredString("file"));
        boolean smooth = o.bool("smooth", false);
        String builder = o.string("bvh", "median");
        if (!builder.equals("median") && !builder.equals("sah")) {
            throw o.source().error(o.raw("bvh"), "unknown bvh builder '" + builder + "'; allowed: median, sah");
        }
        long start = System.nanoTime();
        ObjModel model;
        try {
            model = ObjLoader.load(file, smooth);
        } catch (ObjException e) {
            throw o.source().error(o.raw("file"), e.getMessage());
        }
        long parsed = System.nanoTime();
        List<Material> materials = new ArrayList<>();
        if (override == null) {
            for (ObjMaterial m : model.materials()) {
                materials.add(fromMtl(m, textures, report));
            }
        }
        // the build's time includes the triangles' boxes and renumbering them in leaf order
        long buildStart = System.nanoTime();
        FlatBVH bvh = builder.equals("median")
            ? new MedianSplitBuilder(MEDIAN_LEAF_SIZE).build(MeshBVH.triangleBoxes(model.mesh()))
            : new SahBuilder(SAH_MAX_LEAF_SIZE).build(MeshBVH.triangleBounds(model.mesh()));
        MeshBVH mesh = new MeshBVH(model.mesh(), bvh, materials);
        long built = System.nanoTime();
        report.recordTiming("parse " + file.getFileName(), parsed - start);
        report.recordTiming(builder + " BVH of " + file.getFileName() + " (" + bvh.nodeCount() + " nodes)",
                           built - buildStart);
        report.addStatistic(statistic(file, model));
        model.warnings().forEach(report::addWarning);
        normalMaps(o, model, mesh.triangles(), textures, report);
        mesh.setMaterial(override != null ? override
                         : model.materials().isEmpty() ? MaterialReader.defaultMaterial() : materials.get(0));
        return mesh;
    }

    /** The mesh as loaded: what it renders (triangles, vertices) and how many faces were n-gons. */
    static String statistic(Path file, ObjModel model) {
        return "mesh " + file.getFileName() + ": " + count(model.mesh().triangleCount(), "triangle") + ", "
               + count(model.mesh().vertexCount(), "vertex") + "; " + model.ngons() + " of " + count(model.faces(), "face")
               + " had more than 3 corners (fan-triangulated)";
    }

    private static String count(int n, String what) {
        return n + " " + (n == 1 ? what : what.equals("vertex") ? "vertices" : what + "s");
    }

    /**
     * The object's {@code normal-map: {file, space: tangent | object}} for all its triangles, or
     * {@code none}; without the key, each MTL material's norm / map_Bump read as a tangent-space
     * normal map (OpenGL convention).
     */
    private static void normalMaps(YamlObject o, ObjModel model, TriangleMesh mesh, TextureReader textures, LoadReport report)
            throws SceneException {
        if (o.has("normal-map") && o.raw("normal-map") instanceof org.yaml.snakeyaml.nodes.ScalarNode) {
            String value = o.requiredString("normal-map");
            if (!value.equals("none")) {
                throw o.source().error(o.raw("normal-map"), "'normal-map' is {file, space} or none, got '" + value + "'");
            }
            return; // none: not even the MTL's
        }
        if (o.has("normal-map")) {
            YamlObject map = new YamlObject(o.source(), o.raw("normal-map"), "normal-map", java.util.Set.of("file", "space"));
            String space = map.string("space", "tangent");
            if (!space.equals("tangent") && !space.equals("object")) {
                throw o.source().error(map.raw("space"), "unknown normal-map space '" + space + "'; allowed: object, tangent");
            }
            ImageTexture texture = new ImageTexture(textures.linearImage(o.source().resolve(map.requiredString("file")), map.raw("file")));
            int ids = Math.max(1, model.materials().size());
            for (int id = 0; id < ids; id++) {
                mesh.setNormalMap(id, texture, space.equals("tangent"));
            }
            return;
        }
        for (int id = 0; id < model.materials().size(); id++) {
            ObjMaterial m = model.materials().get(id);
            if (m.mapBump() != null) {
                try {
                    mesh.setNormalMap(id, new ImageTexture(textures.linearImage(m.mapBump(), null)), true);
                } catch (SceneException e) {
                    report.addWarning(e.getMessage() + "; material '" + m.name() + "' has no normal map");
                }
            }
        }
    }

    /**
     * An MTL material onto ours: Ke to a visible emitter; d (or Tr) below 1 to glass of index Ni,
     * with a highlight when Ks and Ns are set, and a warning saying so, since partial dissolve is
     * not blended; otherwise Kd (or map_Kd) to a Lambertian with, when Ks and Ns are set, a Phong
     * lobe. An unreadable map_Kd is a warning.
     */
    static Material fromMtl(ObjMaterial m, TextureReader textures, LoadReport report) {
        Material material = fromMtlValues(m, textures, report);
        material.setName(m.name());
        return material;
    }

    private static Material fromMtlValues(ObjMaterial m, TextureReader textures, LoadReport report) {
        RGBColor kd = new RGBColor(m.kd()[0], m.kd()[1], m.kd()[2]);
        RGBColor ks = new RGBColor(m.ks()[0], m.ks()[1], m.ks()[2]);
        RGBColor ke = new RGBColor(m.ke()[0], m.ke()[1], m.ke()[2]);
        if (ke.max() > 0) {
            return new Emissive(1, ke);
        }
        if (m.dissolve() < 1) {
            // exporters write "Ni 1" whatever the material, and glass of index 1 would be invisible
            double ior = m.ior() > 1 ? m.ior() : MaterialReader.IOR;
            report.addWarning("material '" + m.name() + "': d " + m.dissolve() + " is read as clear glass of index " + ior
                             + " (partial transparency is not blended)");
            boolean lobe = ks.max() > 0 && m.ns() > 0;
            return new Dielectric(ior, RGBColor.BLACK, lobe ? ks.max() : 0, lobe ? m.ns() : MaterialReader.DIELECTRIC_EXPONENT);
        }
        Texture texture = null;
        if (m.mapKd() != null) {
            try {
                texture = new ImageTexture(textures.image(m.mapKd(), null));
            } catch (SceneException e) {
                report.addWarning(e.getMessage() + "; material '" + m.name() + "' uses its Kd colour instead");
            }
        }
        if (ks.max() > 0 && m.ns() > 0) {
            Phong phong = new Phong(MaterialReader.KA, 1, kd, 1, ks, m.ns(), false);
            if (texture != null) {
                phong.setTexture(texture);
            }
            return phong;
        }
        Matte matte = new Matte(MaterialReader.KA, 1, kd);
        if (texture != null) {
            matte.setTexture(texture);
        }
        return matte;
    }
}
