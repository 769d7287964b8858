package raytracer.io.scene;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import raytracer.accel.MeshBVH;
import raytracer.cache.MeshCache;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.Texture;
import raytracer.io.obj.ObjException;
import raytracer.io.obj.ObjLoader;
import raytracer.io.obj.ObjMaterial;
import raytracer.io.obj.ObjModel;
import raytracer.io.ply.PlyException;
import raytracer.io.ply.PlyLoader;
import raytracer.io.ply.PlyModel;
import raytracer.materials.Dielectric;
import raytracer.materials.Emissive;
import raytracer.materials.Matte;
import raytracer.materials.Phong;
import raytracer.materials.ThinDielectric;
import raytracer.math.RGBColor;
import raytracer.textures.ImageTexture;

/**
 * The {@code mesh} objects of one scene: OBJ or PLY files under BVHs. Without a {@code material} key the
 * file's MTL materials are used, mapped onto ours by {@link #fromMtl}. Objects naming one file
 * with the same options share one parse and one tree ({@link SharedMesh}).
 */
final class MeshReader {
    /**
     * Most triangles per leaf of the median-split tree (the report's builder); leaves hold 4 to 8.
     * Against 4: one level less, half the records, and the dragon's frame rays 3-7% faster in the
     * frame-ray harness (6 and 12 measured about the same as 8).
     */
    static final int MEDIAN_LEAF_SIZE = 8;
    /**
     * Most triangles per leaf of the SAH tree (a node of at most this many is a leaf, never split
     * further by the SAH): of 2, 4, 6 and 8, measured on the frame rays, 4 and 8 traced about
     * level and 2 and 6 slower.
     */
    static final int SAH_MAX_LEAF_SIZE = 4;
    /**
     * The builder of a mesh without a {@code bvh} key: the SAH tree renders the dragon and bunny
     * frames 13-14% faster than the median tree, and its build, 1.3-1.4 times as long, is won back
     * within the first render, so the whole run is shorter too (tools/studies/bvh/README.md).
     */
    static final String DEFAULT_BUILDER = "sah";

    private final MeshCache cache;
    /**
     * Per OBJ file and options: the one parse (or cache entry) and tree every object naming them
     * shares, in every frame of an animation ({@link SceneFile} keeps it from frame to frame).
     */
    private final Map<String, SharedMesh> shared;
    /** How many objects name each shared mesh, in the order first named. */
    private final Map<SharedMesh, Integer> users = new LinkedHashMap<>();
    /** Objects that differ only by their transform: one object, instanced. */
    private final Map<ObjectKey, PendingMesh> objects = new HashMap<>();

    /** What makes two mesh objects the same object: the mesh, the material given, the normal maps, shadows. */
    private record ObjectKey(SharedMesh mesh, Material override, String normalMaps, boolean castsShadows) {
    }

    /**
     * The mesh objects of one scene, read from {@code cache} when it has them (null: no cache),
     * sharing the meshes that {@code shared} holds (the frames of an animation) and adding those it
     * reads to it.
     */
    MeshReader(MeshCache cache, Map<String, SharedMesh> shared) {
        this.cache = cache;
        this.shared = shared;
    }

    /**
     * A {@code mesh} object: its OBJ file parsed, or read from the cache, once per file and options
     * for the whole scene; an object that differs from an earlier one only by its transform (which
     * the caller wraps around it: {@code transformed}) is that earlier object.
     */
    GeometricObject read(YamlObject o, Material override, LoadReport report, TextureReader textures, boolean transformed)
            throws SceneException {
        Path file = o.path("file");
        boolean smooth = o.bool("smooth", false);
        String builder = o.string("bvh", DEFAULT_BUILDER);
        if (!builder.equals("median") && !builder.equals("sah")) {
            throw o.source().error(o.raw("bvh"), "unknown bvh builder '" + builder + "'; allowed: median, sah");
        }
        // everything that changes what is cached: the parse's smoothing, the builder and its leaves
        // (the builder by name even when the scene left it to the default, so a change of default
        // reads no entry the other builder made)
        String options = "smooth=" + smooth + " bvh=" + builder + " leaf="
                         + (builder.equals("median") ? MEDIAN_LEAF_SIZE : SAH_MAX_LEAF_SIZE);
        String key = file.toAbsolutePath().normalize() + "\n" + options;
        SharedMesh mesh = shared.get(key);
        if (mesh == null) {
            mesh = SharedMesh.load(o, file, smooth, builder, options, cache, report);
            shared.put(key, mesh);
        } else {
            mesh.inputs().forEach(report::addInput);
        }
        users.merge(mesh, 1, Integer::sum);
        ObjectKey objectKey = new ObjectKey(mesh, override, normalMapKey(o), o.bool("casts-shadows", true));
        PendingMesh same = objects.get(objectKey);
        if (same != null && transformed) {
            return same;
        }
        PendingMesh object = object(o, mesh, override, report, textures);
        if (transformed) {
            objects.put(objectKey, object);
        }
        return object;
    }

    /** One scene object around the shared mesh: its materials (the MTL's unless it names one) and normal maps. */
    private static PendingMesh object(YamlObject o, SharedMesh mesh, Material override, LoadReport report, TextureReader textures)
            throws SceneException {
        List<ObjMaterial> objMaterials = mesh.materials();
        List<Material> materials = new ArrayList<>();
        if (override == null) {
            for (int id = 0; id < objMaterials.size(); id++) {
                materials.add(fromMtl(objMaterials.get(id), mesh.sheets().contains(id), textures, report));
            }
        }
        List<NormalMap> maps = normalMaps(o, objMaterials, textures, report);
        PendingMesh object = new PendingMesh("mesh " + mesh.name(), mesh.bounds(), materials, () -> {
            MeshBVH made = mesh.objectWith(materials, report);
            for (NormalMap map : maps) {
                made.triangles().setNormalMap(map.id(), map.texture(), map.tangent());
            }
            return made;
        });
        object.setMaterial(override != null ? override
                           : objMaterials.isEmpty() ? MaterialReader.defaultMaterial() : materials.get(0));
        return object;
    }

    /** What an object's normal-map key asks for, as a key: the MTL's maps, none, or a file in a space. */
    private static String normalMapKey(YamlObject o) throws SceneException {
        if (!o.has("normal-map")) {
            return "mtl";
        }
        if (o.raw("normal-map") instanceof org.yaml.snakeyaml.nodes.ScalarNode) {
            return "scalar " + o.requiredString("normal-map");
        }
        YamlObject map = new YamlObject(o.source(), o.raw("normal-map"), "normal-map", java.util.Set.of("file", "space"));
        return "file " + map.path("file") + " space " + map.string("space", "tangent");
    }

    /** A line per mesh file that several objects share, for --stats. */
    void reportSharing(LoadReport report) {
        users.forEach((mesh, count) -> {
            if (count > 1) {
                report.addStatistic("mesh " + mesh.name() + ": " + count + " objects share one copy of it");
            }
        });
    }

    /**
     * The mesh file: OBJ, or PLY by its name ({@code .ply}, {@code .ply.gz}), the latter as a model
     * with no materials (a PLY file has none: the object's material applies).
     */
    static ObjModel parse(YamlObject o, Path file, boolean smooth) throws SceneException {
        try {
            if (isPly(file)) {
                PlyModel ply = PlyLoader.load(file, smooth);
                return new ObjModel(ply.parsed(), List.of(), ply.warnings(), ply.faces(), ply.ngons(), List.of(), Set.of());
            }
            return ObjLoader.load(file, smooth);
        } catch (ObjException | PlyException e) {
            throw o.source().error(o.raw("file"), e.getMessage());
        }
    }

    static boolean isPly(Path file) {
        String name = file.getFileName().toString().toLowerCase(java.util.Locale.ROOT);
        return name.endsWith(".ply") || name.endsWith(".ply.gz");
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
