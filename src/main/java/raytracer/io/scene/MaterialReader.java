package raytracer.io.scene;

import java.util.Map;
import java.util.LinkedHashMap;
import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.brdf.BlinnPhong;
import raytracer.brdf.FittedPreset;
import raytracer.brdf.Ward;
import raytracer.core.BRDF;
import raytracer.core.Background;
import raytracer.core.Factory;
import raytracer.core.Material;
import raytracer.core.ParameterException;
import raytracer.core.Parameters;
import raytracer.core.Plugin;
import raytracer.core.Registry;
import raytracer.core.Sampler;
import raytracer.core.Texture;
import raytracer.materials.Dielectric;
import raytracer.materials.Fitted;
import raytracer.materials.GlossyReflector;
import raytracer.materials.Matte;
import raytracer.materials.Phong;
import raytracer.materials.Reflective;
import raytracer.materials.ThinDielectric;
import raytracer.math.RGBColor;

/**
 * One entry of the {@code materials} map, of a type of the {@link Registry}: the built-in ones
 * (docs/scene-format.md) are made here and registered by {@link BuiltInTypes}.
 */
final class MaterialReader {
    static final double KA = 0.2;
    static final double KD = 0.8;
    /** The colour of the default material. */
    static final double DEFAULT_GREY = 0.8;
    static final double KS = 0.2;
    static final double EXPONENT = 20;
    static final double KR = 0.75;
    static final double IOR = 1.5;
    /** A dielectric's highlight exponent: a sharp glint, as polished glass shows. */
    static final double DIELECTRIC_EXPONENT = 1000;
    static final int GLOSSY_SAMPLES = 10;

    private static final Set<String> COMMON = Set.of("type");

    private MaterialReader() {
    }

    /** The material of objects that name none: matte light grey. */
    static Material defaultMaterial() {
        Material m = new Matte(KA, KD, RGBColor.gray(DEFAULT_GREY));
        m.setName("default");
        return m;
    }

    /** The report's fitted models (section 2.2): a preset by name, or explicit rho-d, rho-s and alpha / exponent. */
    static Material ward(Parameters m) throws ParameterException {
        return fitted(m, FittedPreset.Model.WARD);
    }

    static Material wardDuer(Parameters m) throws ParameterException {
        return fitted(m, FittedPreset.Model.WARD_DUER);
    }

    static Material blinnPhong(Parameters m) throws ParameterException {
        return fitted(m, FittedPreset.Model.BLINN_PHONG);
    }

    private static Material fitted(Parameters m, FittedPreset.Model model) throws ParameterException {
        double ka = m.number("ka", 0, 0, false);
        boolean seed = m.bool("seed-compatible", false);
        if (m.has("preset")) {
            try {
                return Fitted.of(FittedPreset.of(m.string("preset", null), model), ka, seed);
            } catch (IllegalArgumentException e) {
                throw m.error("preset", e.getMessage());
            }
        }
        RGBColor rhoD = m.color("rho-d", RGBColor.gray(0.5));
        RGBColor rhoS = m.color("rho-s", RGBColor.gray(0.1));
        BRDF lobe = model == FittedPreset.Model.BLINN_PHONG
            ? new BlinnPhong(rhoS, m.number("exponent", 100, 0, false))
            : new Ward(rhoS, m.number("alpha", 0.1, 0, true), model == FittedPreset.Model.WARD_DUER);
        return new Fitted(rhoD, lobe, ka, seed);
    }

    static Material read(Source source, String name, Node node, TextureReader textures) throws SceneException {
        Material material = readUntextured(source, name, node);
        material.setName(name);
        // the keys were checked against the material's type by readUntextured
        YamlObject keys = new YamlObject(source, node, "material '" + name + "'", AnyName.INSTANCE);
        if (keys.has("texture")) {
            Texture texture = textures.texture(keys.raw("texture"));
            if (material instanceof Matte m) {
                m.setTexture(texture);
            } else if (material instanceof Phong p) {
                p.setTexture(texture);
            } else if (material instanceof GlossyReflector g) {
                g.setTexture(texture);
            } else if (material instanceof Reflective r) {
                r.setTexture(texture);
            }
        }
        if (keys.has("reflection-map")) {
            Background map = textures.environment(keys.raw("reflection-map"), "reflection-map of material '" + name + "'");
            if (material instanceof Reflective r) {
                r.setReflectionMap(map);
            } else if (material instanceof Dielectric d) {
                d.setReflectionMap(map);
            } else if (material instanceof ThinDielectric d) {
                d.setReflectionMap(map);
            } else if (material instanceof GlossyReflector g) {
                g.setReflectionMap(map);
            }
        }
        return material;
    }

    private static Material readUntextured(Source source, String name, Node node) throws SceneException {
        String kind = YamlObject.peekType(source, node, "material '" + name + "'", "matte");
        Plugin<Factory<Material>> type = RegisteredType.find(Registry.standard().materials(), "material", kind, source, node);
        YamlObject m = new YamlObject(source, node, kind + " material '" + name + "'", RegisteredType.keys(COMMON, type));
        return new YamlParameters(m, null).make(type.make(), node, "");
    }

    static Material dielectric(Parameters m) throws ParameterException {
        return new Dielectric(m.number("ior", IOR, 0, true), m.color("absorption", RGBColor.BLACK),
                              m.number("ks", 0, 0, false), m.number("exponent", DIELECTRIC_EXPONENT, 0, true));
    }

    static Material thinDielectric(Parameters m) throws ParameterException {
        return new ThinDielectric(m.number("ior", IOR, 0, true), m.number("ks", 0, 0, false),
                                  m.number("exponent", DIELECTRIC_EXPONENT, 0, true));
    }

    static Material matte(Parameters m) throws ParameterException {
        return new Matte(m.number("ka", KA, 0, false), m.number("kd", KD, 0, false), m.color("color", RGBColor.WHITE));
    }

    static Material phong(Parameters m) throws ParameterException {
        Lit l = lit(m);
        return new Phong(l.ka, l.kd, l.cd, l.ks, l.cs, l.exp, m.bool("normalized", false));
    }

    static Material glossy(Parameters m) throws ParameterException {
        Lit l = lit(m);
        // normalised by default: each glossy ray then weighs about ks cs, as in Suffern's estimator,
        // so the blurred reflection has a mirror's strength; the report's unnormalised lobe would
        // reflect 2 pi / (e + 1) of that (2% at exponent 200), and figure 1b sets it explicitly
        return new GlossyReflector(l.ka, l.kd, l.cd, l.ks, l.cs, l.exp, m.integer("samples", GLOSSY_SAMPLES, 1, Sampler.MAX_SAMPLES),
                                   m.bool("normalized", true));
    }

    static Material reflective(Parameters m) throws ParameterException {
        Lit l = lit(m);
        String fresnel = m.string("fresnel", "none");
        if (!fresnel.equals("none") && !fresnel.equals("schlick")) {
            throw m.error("fresnel", "unknown fresnel '" + fresnel + "'; allowed: none, schlick");
        }
        return new Reflective(l.ka, l.kd, l.cd, l.ks, l.cs, l.exp, m.number("kr", KR, 0, false), m.color("reflect-color", RGBColor.WHITE),
                              fresnel.equals("schlick"));
    }

    /** The values of the book's lit materials beyond the matte's, read in this order: the diffuse and the specular term. */
    private record Lit(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp) {
    }

    private static Lit lit(Parameters m) throws ParameterException {
        double ka = m.number("ka", KA, 0, false);
        double kd = m.number("kd", KD, 0, false);
        RGBColor cd = m.color("color", RGBColor.WHITE);
        double ks = m.number("ks", KS, 0, false);
        RGBColor cs = m.color("specular-color", RGBColor.WHITE);
        return new Lit(ka, kd, cd, ks, cs, m.number("exponent", EXPONENT, 0, true));
    }

    /** The scene's materials section: each named material, in the file's order. */
    static Map<String, Material> readAll(Source source, YamlObject scene, TextureReader textures)
            throws SceneException {
        Map<String, Material> materials = new LinkedHashMap<>();
        if (!scene.has("materials")) {
            return materials;
        }
        Node node = scene.raw("materials");
        YamlObject names = new YamlObject(source, node, "materials", AnyName.INSTANCE);
        for (Map.Entry<String, Node> entry : names.keyNodes().entrySet()) {
            materials.put(entry.getKey(), read(source, entry.getKey(), names.raw(entry.getKey()), textures));
        }
        return materials;
    }
}
