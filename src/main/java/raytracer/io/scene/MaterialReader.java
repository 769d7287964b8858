package raytracer.io.scene;

import java.util.Set;
import org.yaml.snakeyaml.nodes.Node;
import raytracer.brdf.BlinnPhong;
import raytracer.brdf.FittedPreset;
import raytracer.brdf.Ward;
import raytracer.core.BRDF;
import raytracer.core.Background;
import raytracer.core.Material;
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

/** One entry of the {@code materials} map, of any of the types listed in docs/scene-format.md. */
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

    private MaterialReader() {
    }

    /** The material of objects that name none: matte light grey. */
    static Material defaultMaterial() {
        Material m = new Matte(KA, KD, RGBColor.gray(DEFAULT_GREY));
        m.setName("default");
        return m;
    }

    /** A fitted model: a preset by name, or explicit rho-d, rho-s and alpha / exponent. */
    private static Material fitted(YamlObject m, String kind) throws SceneException {
        FittedPreset.Model model = kind.equals("ward") ? FittedPreset.Model.WARD
            : kind.equals("ward-duer") ? FittedPreset.Model.WARD_DUER : FittedPreset.Model.BLINN_PHONG;
        double ka = m.number("ka", 0, 0, false);
        boolean seed = m.bool("seed-compatible", false);
        if (m.has("preset")) {
            try {
                return Fitted.of(FittedPreset.of(m.requiredString("preset"), model), ka, seed);
            } catch (IllegalArgumentException e) {
                throw m.source().error(m.raw("preset"), e.getMessage());
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
        Set<String> allowed = switch (kind) {
            case "matte" -> Set.of("type", "ka", "kd", "color", "texture");
            case "phong" -> Set.of("type", "ka", "kd", "color", "ks", "specular-color", "exponent", "normalized", "texture");
            case "reflective" -> Set.of("type", "ka", "kd", "color", "ks", "specular-color", "exponent", "kr", "reflect-color",
                                        "fresnel", "texture", "reflection-map");
            case "dielectric" -> Set.of("type", "ior", "absorption", "ks", "exponent", "reflection-map");
            case "thin-dielectric" -> Set.of("type", "ior", "ks", "exponent", "reflection-map");
            case "glossy" -> Set.of("type", "ka", "kd", "color", "ks", "specular-color", "exponent", "samples", "normalized",
                                    "texture", "reflection-map");
            case "ward", "ward-duer" -> Set.of("type", "preset", "rho-d", "rho-s", "alpha", "ka", "seed-compatible");
            case "blinn-phong" -> Set.of("type", "preset", "rho-d", "rho-s", "exponent", "ka", "seed-compatible");
            default -> throw source.error(YamlObject.typeNode(node),
                "unknown material type '" + kind + "'; allowed: blinn-phong, dielectric, glossy, matte, phong, reflective, "
                + "thin-dielectric, ward, ward-duer");
        };
        YamlObject m = new YamlObject(source, node, kind + " material '" + name + "'", allowed);
        if (kind.startsWith("ward") || kind.equals("blinn-phong")) {
            return fitted(m, kind);
        }
        if (kind.equals("dielectric")) {
            return new Dielectric(m.number("ior", IOR, 0, true), m.color("absorption", RGBColor.BLACK),
                                  m.number("ks", 0, 0, false), m.number("exponent", DIELECTRIC_EXPONENT, 0, true));
        }
        if (kind.equals("thin-dielectric")) {
            return new ThinDielectric(m.number("ior", IOR, 0, true), m.number("ks", 0, 0, false),
                                      m.number("exponent", DIELECTRIC_EXPONENT, 0, true));
        }
        double ka = m.number("ka", KA, 0, false);
        double kd = m.number("kd", KD, 0, false);
        RGBColor cd = m.color("color", RGBColor.WHITE);
        if (kind.equals("matte")) {
            return new Matte(ka, kd, cd);
        }
        double ks = m.number("ks", KS, 0, false);
        RGBColor cs = m.color("specular-color", RGBColor.WHITE);
        double exp = m.number("exponent", EXPONENT, 0, true);
        if (kind.equals("phong")) {
            return new Phong(ka, kd, cd, ks, cs, exp, m.bool("normalized", false));
        }
        if (kind.equals("glossy")) {
            return new GlossyReflector(ka, kd, cd, ks, cs, exp, m.integer("samples", GLOSSY_SAMPLES, 1, Sampler.MAX_SAMPLES), m.bool("normalized", false));
        }
        String fresnel = m.string("fresnel", "none");
        if (!fresnel.equals("none") && !fresnel.equals("schlick")) {
            throw source.error(m.raw("fresnel"), "unknown fresnel '" + fresnel + "'; allowed: none, schlick");
        }
        return new Reflective(ka, kd, cd, ks, cs, exp, m.number("kr", KR, 0, false), m.color("reflect-color", RGBColor.WHITE),
                              fresnel.equals("schlick"));
    }
}
