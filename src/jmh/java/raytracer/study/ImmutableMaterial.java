package raytracer.study;

import raytracer.math.RGBColor;

/** Suffern's Material::shade (chapter 14) as the textbook's Java writes it: it returns a new colour. */
interface ImmutableMaterial {

    /** The radiance leaving {@code hit} towards the viewer; {@code whitted} has the lights and traces rays. */
    RGBColor shade(Hit hit, ImmutableWhitted whitted);
}
