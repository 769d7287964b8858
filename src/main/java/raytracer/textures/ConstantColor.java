package raytracer.textures;

import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.math.RGBColor;
import raytracer.math.MutableRgb;

/**
 * The same colour everywhere (Suffern, section 29.2): the texture counterpart of a material's plain
 * colour, for scenes that swap textures in and out. A plain colour skips the lookup.
 */
public final class ConstantColor implements Texture {
    private final RGBColor color;

    public ConstantColor(RGBColor color) {
        this.color = color;
    }

    @Override
    public void getColor(ShadeRec sr, MutableRgb out) {
        out.set(color);
    }

    @Override
    public boolean usesTextureCoordinates() {
        return false;
    }

    public RGBColor constantColor() {
        return color;
    }
}
