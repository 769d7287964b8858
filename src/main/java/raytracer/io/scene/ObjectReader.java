package raytracer.io.scene;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.yaml.snakeyaml.nodes.MappingNode;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.nodes.NodeTuple;
import org.yaml.snakeyaml.nodes.ScalarNode;
import org.yaml.snakeyaml.nodes.Tag;
import raytracer.core.Factory;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.ParameterException;
import raytracer.core.Parameters;
import raytracer.core.Plugin;
import raytracer.core.Registry;
import raytracer.math.Matrix4;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.Vector3D;
import raytracer.shapes.Box;
import raytracer.shapes.Cylinder;
import raytracer.shapes.Instance;
import raytracer.shapes.Plane;
import raytracer.shapes.Sphere;
import raytracer.shapes.Triangle;

/**
 * One entry of the {@code objects} list: a shape of a type of the {@link Registry} (the built-in
 * ones are made here and registered by {@link BuiltInTypes}), its material and an optional
 * transform.
 */
final class ObjectReader {
    // and an optional name, by which an animation moves the object (Animation, SceneFile)
    private static final Set<String> COMMON = Set.of("type", "name", "material", "transform", "casts-shadows");

    private ObjectReader() {
    }

    /**
     * What a mesh needs beside its values: the scene's materials (the one it names replaces its
     * file's), the report, the images, the meshes read so far, and whether a transform will be
     * wrapped around it.
     */
    record Context(Map<String, Material> materials, LoadReport report, TextureReader textures, MeshReader meshes,
                   boolean transformed) {
    }

    /**
     * The object of {@code node}; {@code motion}, when not null, is the animation's transform of it
     * at this frame, applied after its own ({@code motionNode} and {@code when} place a message
     * about it: " at frame 12").
     */
    static GeometricObject read(Source source, Node node, Map<String, Material> materials, LoadReport report,
                                TextureReader textures, MeshReader meshes, Matrix4 motion, Node motionNode, String when)
            throws SceneException {
        String kind = YamlObject.peekType(source, node, "object", null);
        Plugin<Factory<GeometricObject>> type = RegisteredType.find(Registry.standard().objects(), "object", kind, source, node);
        YamlObject o = new YamlObject(source, node, kind, RegisteredType.keys(COMMON, type));
        Context context = new Context(materials, report, textures, meshes, o.has("transform") || motion != null);
        GeometricObject shape = new YamlParameters(o, context).make(type.make(), node, kind + ": ");
        if (shape.getMaterial() == null) {
            // a mesh has its material already: the one named, or its file's
            shape.setMaterial(material(o, materials));
        }
        shape.setCastsShadows(o.bool("casts-shadows", true));
        if (!o.has("transform") && motion == null) {
            return shape;
        }
        Matrix4 m = o.has("transform") ? TransformReader.read(source, o.raw("transform")) : Matrix4.IDENTITY;
        Node where = o.has("transform") ? o.raw("transform") : node;
        if (motion != null) {
            m = TransformReader.checked(source, motionNode, motion.multiply(m), when);
            where = motionNode;
        }
        Instance instance;
        try {
            instance = new Instance(shape, m);
        } catch (IllegalArgumentException e) {
            throw source.error(where, e.getMessage());
        }
        instance.setCastsShadows(shape.castsShadows());
        return instance;
    }

    /** The object's {@code name}, or null when it has none; read before the object, to check the animation's names. */
    static String name(Source source, Node node) throws SceneException {
        if (!(node instanceof MappingNode mapping)) {
            return null;
        }
        for (NodeTuple tuple : mapping.getValue()) {
            if (tuple.getKeyNode() instanceof ScalarNode key && key.getValue().equals("name")) {
                if (!(tuple.getValueNode() instanceof ScalarNode value)
                    || value.getTag().equals(Tag.NULL)) {
                    throw source.error(tuple.getValueNode(), "'name' of an object must be a single value, got "
                                       + YamlScalars.describe(tuple.getValueNode()));
                }
                return value.getValue();
            }
        }
        return null;
    }

    static GeometricObject sphere(Parameters o) throws ParameterException {
        return new Sphere(o.requiredPoint("center"), o.number("radius", 1, 0, true));
    }

    static GeometricObject plane(Parameters o) throws ParameterException {
        Vector3D n = o.requiredVector("normal");
        return new Plane(o.point("point", Point3D.ORIGIN), new Normal(n.x(), n.y(), n.z()));
    }

    static GeometricObject box(Parameters o) throws ParameterException {
        return new Box(o.requiredPoint("min"), o.requiredPoint("max"));
    }

    static GeometricObject cylinder(Parameters o) throws ParameterException {
        return new Cylinder(o.number("bottom", 0), o.number("top", 1), o.number("radius", 1, 0, true), o.bool("closed", true));
    }

    /** A mesh object: the file's triangles, with the material named or the file's own (MeshReader). */
    static GeometricObject mesh(YamlParameters p) throws SceneException {
        Context c = p.context(Context.class);
        YamlObject o = p.values();
        return c.meshes().read(o, o.has("material") ? material(o, c.materials()) : null, c.report(), c.textures(), c.transformed());
    }

    static GeometricObject triangle(YamlParameters parameters) throws SceneException {
        YamlObject o = parameters.values();
        List<Node> vertices = o.list("vertices");
        if (vertices.size() != 3) {
            throw o.source().error(o.required("vertices"), "'vertices' of a triangle must list 3 points, got " + vertices.size());
        }
        Point3D[] p = new Point3D[3];
        for (int i = 0; i < 3; i++) {
            double[] t = YamlScalars.triple(o.source(), vertices.get(i), "vertex " + (i + 1) + " of the triangle");
            p[i] = new Point3D(t[0], t[1], t[2]);
        }
        return new Triangle(p[0], p[1], p[2]);
    }

    private static Material material(YamlObject o, Map<String, Material> materials) throws SceneException {
        if (!o.has("material")) {
            return MaterialReader.defaultMaterial();
        }
        String name = o.requiredString("material");
        Material m = materials.get(name);
        if (m == null) {
            throw o.source().error(o.raw("material"), "material '" + name + "' is not defined; defined: "
                                   + (materials.isEmpty() ? "none" : YamlScalars.names(materials.keySet())));
        }
        return m;
    }
}
