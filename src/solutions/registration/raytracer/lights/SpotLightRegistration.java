package raytracer.lights;

import java.util.Set;
import raytracer.core.Registrar;
import raytracer.core.Registration;
import raytracer.math.RGBColor;

/**
 * Exercise 3's light: {@code {type: spot, position, direction, intensity (1), color (white),
 * total-angle (degrees, 30), falloff-start (the total angle)}} in a scene's lights.
 */
public final class SpotLightRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.light("spot", Set.of("position", "direction", "intensity", "color", "total-angle", "falloff-start"), p -> {
            double intensity = p.number("intensity", 1, 0, false);
            RGBColor color = p.color("color", RGBColor.WHITE);
            p.checkEmission("intensity", intensity, "color", color);
            double total = p.number("total-angle", 30);
            return new SpotLight(intensity, color, p.requiredPoint("position"), p.requiredVector("direction"), total,
                                 p.number("falloff-start", total));
        });
    }
}
