package raytracer.core;

import raytracer.math.MutableRgb;
import raytracer.math.RGBColor;

/** A colour that varies over a surface (Suffern, chapter 29): looked up from the completed hit. */
public interface Texture {

    /** Writes the texture's linear colour at the hit (its u, v or local hit point) into {@code out}. */
    void getColor(ShadeRec sr, MutableRgb out);

    /**
     * Whether the colour depends on the hit's u, v: false for a constant colour, so that shapes
     * whose u, v cost inverse trigonometry (spheres, cylinders) may leave them out.
     */
    default boolean usesTextureCoordinates() {
        return true;
    }

    /** The colour of a texture that is the same everywhere, or null: a BRDF may then read it as a plain colour. */
    default RGBColor constantColor() {
        return null;
    }
}
