package raytracer.materials;

import java.util.Set;
import raytracer.brdf.CookTorrance;
import raytracer.core.Registrar;
import raytracer.core.Registration;
import raytracer.math.RGBColor;

/**
 * Exercise 7's BRDF as a material: {@code {type: cook-torrance, rho-d (0.5), f0 (0.04), roughness
 * (0.3), ka (0)}}, the fitted material's Lambertian term beside the Cook-Torrance lobe.
 */
public final class CookTorranceRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.material("cook-torrance", Set.of("rho-d", "f0", "roughness", "ka"), p -> {
            CookTorrance lobe = new CookTorrance(p.color("f0", RGBColor.gray(0.04)), p.number("roughness", 0.3, 0, true));
            return new Fitted(p.color("rho-d", RGBColor.gray(0.5)), lobe, p.number("ka", 0, 0, false), false);
        });
    }
}
