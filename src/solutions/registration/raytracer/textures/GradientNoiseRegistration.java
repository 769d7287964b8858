package raytracer.textures;

import java.util.Set;
import raytracer.core.Registrar;
import raytracer.core.Registration;
import raytracer.math.RGBColor;

/** Exercise 8's texture: {@code texture: {type: noise, color-a (low), color-b (high), scale (0.25)}}. */
public final class GradientNoiseRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.texture("noise", Set.of("color-a", "color-b", "scale"), p -> new GradientNoise(
            p.color("color-a", RGBColor.gray(0.1)), p.color("color-b", RGBColor.WHITE), p.number("scale", 0.25, 0, true)));
    }
}
