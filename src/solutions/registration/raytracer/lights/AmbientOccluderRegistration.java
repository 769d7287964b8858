package raytracer.lights;

import java.util.Set;
import raytracer.core.Registrar;
import raytracer.core.Registration;
import raytracer.math.RGBColor;

/** Exercise 4's ambient light: {@code ambient: {type: occlusion, radiance (1), color (white), samples (16)}}. */
public final class AmbientOccluderRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.ambient("occlusion", Set.of("radiance", "color", "samples"), p -> {
            double radiance = p.number("radiance", 1, 0, false);
            RGBColor color = p.color("color", RGBColor.WHITE);
            p.checkEmission("radiance", radiance, "color", color);
            return new AmbientOccluder(radiance, color, p.integer("samples", 16, 1, Integer.MAX_VALUE));
        });
    }
}
