package raytracer.materials;

import java.util.List;
import raytracer.core.BRDF;
import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.core.Skip;
import raytracer.core.Skipped;
import raytracer.core.World;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * A material's {@link DirectLighting} as the scene analysis leaves it: without the terms that are
 * zero at every hit of the scene (a ka, kd or ks of 0, an ambient light of zero radiance), each
 * counted where it would have been evaluated ({@link Skipped}), and with constant textures read as
 * plain colours. Each left-out term would have added +0, so the image is the same to the bit.
 * When no term is left, the surface reflects no direct light: an {@link UnlitSurface} takes its place.
 */
final class SimplifiedLighting implements Lighting {
    /** The book's lighting with the zero terms replaced ({@link LeftOutTerm}; no ambient BRDF when it is zero). */
    private final DirectLighting lighting;
    private final boolean ambientLeftOut;
    private final boolean lobeLeftOut;

    private SimplifiedLighting(DirectLighting lighting, boolean ambientLeftOut, boolean lobeLeftOut) {
        this.lighting = lighting;
        this.ambientLeftOut = ambientLeftOut;
        this.lobeLeftOut = lobeLeftOut;
    }

    /**
     * {@code lighting} for the render of {@code world}, with what is left out added to
     * {@code skips}, named for {@code material}; {@code lighting} itself when nothing is.
     */
    static Lighting of(DirectLighting lighting, World world, String material, List<Skip> skips) {
        String of = "material '" + material + "'";
        BRDF a = lighting.ambient.simplified();
        BRDF d = lighting.diffuse.simplified();
        BRDF s = lighting.specular == null ? null : lighting.specular.simplified();
        boolean constants = a != lighting.ambient || d != lighting.diffuse || s != lighting.specular;
        if (constants) {
            skips.add(new Skip(Skipped.UNCOUNTED, "constant texture read as a plain colour", of));
        }
        boolean noAmbient = world.ambient().isBlack() || a.isBlack();
        boolean noDiffuse = d.isBlack();
        boolean noLobe = s != null && s.isBlack();
        boolean dark = noAmbient && noDiffuse && (s == null || noLobe);
        if (noAmbient) {
            skips.add(new Skip(Skipped.AMBIENT_TERMS, "ambient term not evaluated",
                               of + (a.isBlack() ? ": its ambient reflectance is 0" : ": the ambient light is black")));
        }
        if (dark) {
            skips.add(new Skip(Skipped.LIGHT_SAMPLES, "lights not evaluated, no shadow rays", of + ": no term reflects direct light"));
            return new UnlitSurface();
        }
        if (noDiffuse) {
            skips.add(new Skip(Skipped.DIFFUSE_TERMS, "diffuse term not evaluated", of + ": its diffuse reflectance is 0"));
            d = new LeftOutTerm(Skipped.DIFFUSE_TERMS);
        }
        if (noLobe) {
            skips.add(new Skip(Skipped.SPECULAR_LOBES, "specular lobe not evaluated", of + ": its specular reflectance is 0"));
            s = new LeftOutTerm(Skipped.SPECULAR_LOBES);
        }
        if (!noAmbient && !noDiffuse && !noLobe) {
            return constants ? new DirectLighting(a, d, s, lighting.terms, lighting.mis) : lighting;
        }
        DirectLighting kept = new DirectLighting(noAmbient ? null : a, d, s, lighting.terms, noLobe ? null : lighting.mis);
        return new SimplifiedLighting(kept, noAmbient, noLobe);
    }

    @Override
    public void shade(ShadeRec sr, MutableRgb L) {
        lighting.shade(sr, L);
        countAmbient(sr);
    }

    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb L) {
        lighting.areaLightShade(sr, L);
        countAmbient(sr);
    }

    @Override
    public int lightSamplesToward(ShadeRec sr, Light light, MutableVec3 wi) {
        return lobeLeftOut ? 0 : lighting.lightSamplesToward(sr, light, wi);
    }

    /** Counts the ambient term left out of a hit that shows direct light. */
    private void countAmbient(ShadeRec sr) {
        if (ambientLeftOut && sr.scratch.policy.showsDirect(sr.depth)) {
            sr.scratch.skipped[Skipped.AMBIENT_TERMS]++;
        }
    }
}
