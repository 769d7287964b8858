package raytracer.brdf;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import raytracer.math.RGBColor;

/**
 * The report's figure 2 materials: Ngan, Durand and Matusik's 2005 fits of three MERL materials to
 * Ward, Ward-Duer and Blinn-Phong (values and their sources: docs/brdf-params.md). Each gives a
 * diffuse rho_d, a specular rho_s and the lobe's alpha (Ward) or exponent n (Blinn-Phong).
 */
public enum FittedPreset {
    NICKEL_WARD("nickel", Model.WARD, rgb(0.0221, 0.0178, 0.0107), rgb(0.204, 0.154, 0.0946), 0.0432),
    NICKEL_WARD_DUER("nickel", Model.WARD_DUER, rgb(0.0388, 0.0291, 0.0159), rgb(0.107, 0.0828, 0.054), 0.0424),
    NICKEL_BLINN_PHONG("nickel", Model.BLINN_PHONG, rgb(0.0301, 0.0257, 0.0173), rgb(0.0665, 0.0486, 0.0285), 1040),
    GREEN_ACRYLIC_WARD("green-acrylic", Model.WARD, rgb(0.0164, 0.0641, 0.0238), rgb(0.0101, 0.00793, 0.00495), 0.0141),
    GREEN_ACRYLIC_WARD_DUER("green-acrylic", Model.WARD_DUER, rgb(0.0165, 0.064, 0.0239), rgb(0.0068, 0.00548, 0.00335), 0.0137),
    GREEN_ACRYLIC_BLINN_PHONG("green-acrylic", Model.BLINN_PHONG, rgb(0.0183, 0.0657, 0.0248), rgb(0.00161, 0.00121, 0.000781), 28400),
    DELRIN_WARD("delrin", Model.WARD, rgb(0.293, 0.244, 0.146), rgb(0.0348, 0.0295, 0.0202), 0.162),
    DELRIN_WARD_DUER("delrin", Model.WARD_DUER, rgb(0.292, 0.244, 0.146), rgb(0.0238, 0.0198, 0.0133), 0.146),
    DELRIN_BLINN_PHONG("delrin", Model.BLINN_PHONG, rgb(0.299, 0.249, 0.15), rgb(0.00755, 0.00654, 0.00461), 83.4);

    /** The three fitted lobes. */
    public enum Model {
        WARD("ward"), WARD_DUER("ward-duer"), BLINN_PHONG("blinn-phong");

        private final String key;

        Model(String key) {
            this.key = key;
        }

        public String key() {
            return key;
        }
    }

    private final String material;
    private final Model model;
    private final RGBColor rhoD;
    private final RGBColor rhoS;
    private final double roughness;

    FittedPreset(String material, Model model, RGBColor rhoD, RGBColor rhoS, double roughness) {
        this.material = material;
        this.model = model;
        this.rhoD = rhoD;
        this.rhoS = rhoS;
        this.roughness = roughness;
    }

    private static RGBColor rgb(double r, double g, double b) {
        return new RGBColor(r, g, b);
    }

    /** The preset for a material name and model; IllegalArgumentException listing the choices otherwise. */
    public static FittedPreset of(String material, Model model) {
        return Arrays.stream(values()).filter(p -> p.material.equals(material.toLowerCase(Locale.ROOT)) && p.model == model)
            .findFirst().orElseThrow(() -> new IllegalArgumentException(
                "unknown preset '" + material + "'; allowed: " + String.join(", ", materials())));
    }

    public static List<String> materials() {
        return List.of("delrin", "green-acrylic", "nickel");
    }

    /** The specular lobe of this preset. */
    public raytracer.core.BRDF specular() {
        return model == Model.BLINN_PHONG ? new BlinnPhong(rhoS, roughness) : new Ward(rhoS, roughness, model == Model.WARD_DUER);
    }

    public RGBColor rhoD() {
        return rhoD;
    }

    public RGBColor rhoS() {
        return rhoS;
    }

    public double roughness() {
        return roughness;
    }

    public Model model() {
        return model;
    }
}
