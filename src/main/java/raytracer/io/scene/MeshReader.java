package raytracer.io.scene;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import raytracer.accel.MeshBVH;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.Texture;
import raytracer.image.FileKind;
import raytracer.io.obj.ObjException;
import raytracer.io.obj.ObjLoader;
import raytracer.io.obj.ObjMaterial;
import raytracer.io.obj.ObjModel;
import raytracer.materials.Dielectric;
import raytracer.materials.Emissive;
import raytracer.materials.Matte;
import raytracer.materials.Phong;
import raytracer.materials.ThinDielectric;
import raytracer.math.RGBColor;
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

    static GeometricObject read(YamlObject o, Material override, LoadReport report, TextureReader textures,
                                MeshCache cache) throws SceneException {
        Path file = o.path("file");
        boolean smooth = o.bool("smooth", false);
        String builder = o.string("bvh", "median");
        if (!builder.equals("median") && !builder.equals("sah")) {
            throw o.source().error(o.raw("bvh"), "unknown bvh builder '" + builder + "'; allowed: median, sah");
        }
        String name = file.getFileName().toString();
        // everything that changes what is cached: the parse's smoothing, the builder and its leaves
        String options = "smooth=" + smooth + " bvh=" + builder + " leaf="
                         + (builder.equals("median") ? MEDIAN_LEAF_SIZE : SAH_MAX_LEAF_SIZE);
        report.addInput(file);
        String notRegular = FileKind.notRegular(file);
        if (notRegular != null) {
            // before the cache's checksum of the file, which would block on a FIFO as a parse would
            throw o.source().error(o.raw("file"), "cannot read mesh " + file + ": " + notRegular);
        }
        long lookupStart = System.nanoTime();
        MeshCache.Lookup lookup = cache == null ? null : cache.lookup(file, options, report::addWarning);
        long readNanos = System.nanoTime() - lookupStart;
        MeshCacheFile.Header cached = lookup == null ? null : lookup.header();
        ObjModel model = null;
        long parseNanos = 0;
        if (cached == null) {
            long start = System.nanoTime();
            model = parse(o, file, smooth);
            parseNanos = System.nanoTime() - start;
            report.recordTiming("parse " + name, parseNanos);
            model.warnings().forEach(report::addWarning);
            report.addStatistic(statistic(name, model.mesh().triangleCount(), model.mesh().vertexCount(), model.ngons(),
                                          model.faces()));
            model.libraries().forEach(report::addInput);
        } else {
            report.addStatistic(statistic(name, cached.triangles(), cached.vertices(), cached.ngons(), cached.faces()));
            cached.libraries().forEach(library -> report.addInput(Path.of(library.path())));
        }
        List<ObjMaterial> objMaterials = cached != null ? cached.materials() : model.materials();
        Set<Integer> sheets = cached != null ? cached.sheets() : model.sheets();
        List<Material> materials = new ArrayList<>();
        if (override == null) {
            for (int id = 0; id < objMaterials.size(); id++) {
                materials.add(fromMtl(objMaterials.get(id), sheets.contains(id), textures, report));
            }
        }
        List<NormalMap> maps = normalMaps(o, objMaterials, textures, report);
        Build build = new Build(o, file, smooth, builder, materials, report, lookup);
        ObjModel parsed = model;
        long parsedIn = parseNanos;
        PendingMesh mesh = new PendingMesh("mesh " + name, cached != null ? cached.bounds() : model.mesh().bounds(), materials,
                                           () -> {
                                               MeshBVH made = cached != null ? build.fromCache(lookup.take(), readNanos) : build.of(parsed, parsedIn);
                                               for (NormalMap map : maps) {
                                                   made.triangles().setNormalMap(map.id(), map.texture(), map.tangent());
                                               }
                                               return made;
                                           });
        mesh.setMaterial(override != null ? override
                         : objMaterials.isEmpty() ? MaterialReader.defaultMaterial() : materials.get(0));
        return mesh;
    }

    static ObjModel parse(YamlObject o, Path file, boolean smooth) throws SceneException {
        try {
            return ObjLoader.load(file, smooth);
        } catch (ObjException e) {
            throw o.source().error(o.raw("file"), e.getMessage());
        }
    }

    /** The mesh as loaded: what it renders (triangles, vertices) and how many faces were n-gons. */
    static String statistic(String name, int triangles, int vertices, int ngons, int faces) {
        return "mesh " + name + ": " + count(triangles, "triangle") + ", " + count(vertices, "vertex") + "; " + ngons + " of "
               + count(faces, "face") + " had more than 3 corners (fan-triangulated)";
    }

    private static String count(int n, String what) {
        return n + " " + (n == 1 ? what : what.equals("vertex") ? "vertices" : what + "s");
    }

    /** A normal map for the triangles of one material id. */
    record NormalMap(int id, Texture texture, boolean tangent) {
    }

    /**
     * The object's {@code normal-map: {file, space: tangent | object}} for all its triangles, or
     * {@code none}; without the key, each MTL material's norm / map_Bump read as a tangent-space
     * normal map (OpenGL convention). The textures are read now; they are set when the mesh is made.
     */
    private static List<NormalMap> normalMaps(YamlObject o, List<ObjMaterial> materials, TextureReader textures,
                                              LoadReport report) throws SceneException {
        List<NormalMap> maps = new ArrayList<>();
        if (o.has("normal-map") && o.raw("normal-map") instanceof org.yaml.snakeyaml.nodes.ScalarNode) {
            String value = o.requiredString("normal-map");
            if (!value.equals("none")) {
                throw o.source().error(o.raw("normal-map"), "'normal-map' is {file, space} or none, got '" + value + "'");
            }
            return maps; // none: not even the MTL's
        }
        if (o.has("normal-map")) {
            YamlObject map = new YamlObject(o.source(), o.raw("normal-map"), "normal-map", java.util.Set.of("file", "space"));
            String space = map.string("space", "tangent");
            if (!space.equals("tangent") && !space.equals("object")) {
                throw o.source().error(map.raw("space"), "unknown normal-map space '" + space + "'; allowed: object, tangent");
            }
            ImageTexture texture = new ImageTexture(textures.linearImage(map.path("file"), map.raw("file")));
            int ids = Math.max(1, materials.size());
            for (int id = 0; id < ids; id++) {
                maps.add(new NormalMap(id, texture, space.equals("tangent")));
            }
            return maps;
        }
        for (int id = 0; id < materials.size(); id++) {
            ObjMaterial m = materials.get(id);
            if (m.mapBump() != null) {
                try {
                    maps.add(new NormalMap(id, new ImageTexture(textures.linearImage(m.mapBump(), null)), true));
                } catch (SceneException e) {
                    report.addWarning(e.getMessage() + "; material '" + m.name() + "' has no normal map");
                }
            }
        }
        return maps;
    }

    /**
     * An MTL material onto ours: Ke to a visible emitter; d (or Tr) below 1 to glass of index Ni,
     * with a highlight when Ks and Ns are set, and a warning saying so, since partial dissolve is
     * not blended: a thin sheet of it ({@link ThinDielectric}) when its triangles leave an edge
     * open ({@code sheet}), the surface of a solid ({@link Dielectric}) when they close; otherwise
     * Kd (or map_Kd) to a Lambertian with, when Ks and Ns are set, a Phong lobe. An unreadable
     * map_Kd is a warning.
     */
    static Material fromMtl(ObjMaterial m, boolean sheet, TextureReader textures, LoadReport report) {
        Material material = fromMtlValues(m, sheet, textures, report);
        material.setName(m.name());
        return material;
    }

    private static Material fromMtlValues(ObjMaterial m, boolean sheet, TextureReader textures, LoadReport report) {
        RGBColor kd = new RGBColor(m.kd()[0], m.kd()[1], m.kd()[2]);
        RGBColor ks = new RGBColor(m.ks()[0], m.ks()[1], m.ks()[2]);
        RGBColor ke = new RGBColor(m.ke()[0], m.ke()[1], m.ke()[2]);
        if (ke.max() > 0) {
            return new Emissive(1, ke);
        }
        if (m.seeThrough()) {
            // exporters write "Ni 1" whatever the material, and glass of index 1 would be invisible
            double ior = m.ior() > 1 ? m.ior() : MaterialReader.IOR;
            report.addWarning("material '" + m.name() + "': d " + m.dissolve() + " is read as "
                              + (sheet ? "a thin sheet of clear glass of index " + ior + ", since its triangles leave an edge open"
                                       : "clear glass of index " + ior) + " (partial transparency is not blended)");
            boolean lobe = ks.max() > 0 && m.ns() > 0;
            double highlight = lobe ? ks.max() : 0;
            double exponent = lobe ? m.ns() : MaterialReader.DIELECTRIC_EXPONENT;
            return sheet ? new ThinDielectric(ior, highlight, exponent) : new Dielectric(ior, RGBColor.BLACK, highlight, exponent);
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
