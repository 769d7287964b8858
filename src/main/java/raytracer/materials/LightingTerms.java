package raytracer.materials;

import raytracer.math.MutableRgb;

/**
 * How a light sample's diffuse term f_d and specular term f_s meet cos(theta_i) in
 * {@link DirectLighting}: as the reflection equation has it, or as the 2015 report computed them.
 */
enum LightingTerms {
    /** (f_d + f_s) cos(theta_i), the integrand of the reflection equation. */
    PHYSICAL {
        @Override
        void combine(MutableRgb f, MutableRgb fs, double cos) {
            if (fs != null) {
                f.add(fs);
            }
            f.scale(cos);
        }
    },
    /**
     * The report's quirks (docs/brdf-params.md), for its figure 2's brightness: f_d pi cos(theta_i)
     * + f_s, the diffuse term without its 1/pi and the specular one without cos(theta_i).
     */
    REPORT {
        @Override
        void combine(MutableRgb f, MutableRgb fs, double cos) {
            f.scale(Math.PI * cos);
            if (fs != null) {
                f.add(fs);
            }
        }
    };

    /** Turns {@code f}, holding f_d, into the factor that meets the light; {@code fs} is f_s, or null without one. */
    abstract void combine(MutableRgb f, MutableRgb fs, double cos);
}
