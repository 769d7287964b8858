package raytracer.materials;

import java.util.List;
import raytracer.core.BRDF;
import raytracer.core.Light;
import raytracer.core.PixelSamples;
import raytracer.core.ShadeRec;
import raytracer.core.Skip;
import raytracer.core.Skipped;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * The direct light of a lit material, ambient plus a diffuse and an optional specular lobe, in the
 * book's two forms: {@link #shade} takes each light from its one direction (Suffern's Matte::shade
 * and Phong::shade, sections 14.7 and 15.5: L = rho_a La + sum over lights of f L cos(theta_i)),
 * {@link #areaLightShade} averages each light's samples (chapter 18's area_light_shade:
 * f L G cos(theta_i) / pdf, with G = pdf = 1 for lights without extent, so both give the same for
 * them). {@link #addSample} is the body of the book's loop: a light behind the surface or behind
 * an occluder adds nothing.
 *
 * <p>Beyond the book, each in a helper of its own so that those three read as the book's: the
 * report's variant of the terms ({@link LightingTerms}); the adaptive cutoff, which leaves out a
 * sample too faint to change the pixel before its shadow ray is traced ({@link #negligible}); a
 * glossy reflector's highlight weighed against its glossy rays ({@link GlossyLightMis}); and
 * {@link #simplified}, which leaves out the terms that are zero at every hit of a scene (each
 * would have added +0, so the image is the same to the bit) and counts the work it saves.
 */
final class DirectLighting {

    private final BRDF ambient;
    private final BRDF diffuse;
    private final BRDF specular;
    private final LightingTerms terms;
    /**
     * For a glossy reflector: how its lobe's term for a light sample is weighed against its glossy
     * rays, which may find the same light (null: every light is found by its samples alone).
     */
    private final GlossyLightMis mis;
    /** Terms left out by {@link #simplified}: zero at every hit, so counted instead of evaluated. */
    private final boolean ambientZero;
    private final boolean diffuseZero;
    private final boolean specularZero;
    /** All three zero: the surface reflects no direct light, and the lights are not evaluated. */
    private final boolean dark;

    /** {@code specular} may be null (a matte surface). */
    DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular, LightingTerms terms) {
        this(ambient, diffuse, specular, terms, null, false, false, false);
    }

    DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular) {
        this(ambient, diffuse, specular, LightingTerms.PHYSICAL);
    }

    /** The direct light of a glossy reflector, whose glossy rays also find visible area lights ({@link GlossyLightMis}). */
    DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular, GlossyLightMis mis) {
        this(ambient, diffuse, specular, LightingTerms.PHYSICAL, mis, false, false, false);
    }

    private DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular, LightingTerms terms, GlossyLightMis mis,
                           boolean ambientZero, boolean diffuseZero, boolean specularZero) {
        this.ambient = ambient;
        this.diffuse = diffuse;
        this.specular = specular;
        this.terms = terms;
        this.mis = mis;
        this.ambientZero = ambientZero;
        this.diffuseZero = diffuseZero;
        this.specularZero = specularZero;
        this.dark = ambientZero && diffuseZero && (specular == null || specularZero);
    }

    /** Suffern's shade: writes into {@code L} the ambient term plus each light's, from its one direction. */
    void shade(ShadeRec sr, MutableRgb L) {
        if (!ambient(sr, L)) {
            return;
        }
        if (dark) {
            countUnlit(sr, false);
            return;
        }
        for (Light light : sr.world.lights()) {
            double distance = light.getDirection(sr, sr.wi);
            addSample(sr, light, distance, 1, 1, 1, L);
        }
    }

    /**
     * Suffern's area_light_shade: writes into {@code L} the ambient term plus, for each light, the
     * average over its samples of f L G cos(theta_i) / pdf (one sample for lights without extent).
     * A light with extent takes the values of its dimension, stratified across the pixel's samples
     * ({@link PixelSamples}), as many as the ray tree's policy gives a hit at this depth.
     */
    void areaLightShade(ShadeRec sr, MutableRgb L) {
        if (!ambient(sr, L)) {
            return;
        }
        if (dark) {
            countUnlit(sr, true);
            return;
        }
        for (Light light : sr.world.lights()) {
            if (!light.mayIlluminate(sr)) {
                continue; // every sample would weigh nothing: draw none
            }
            int n = samplesAt(sr, light);
            int strata = strata(sr, light);
            for (int j = 0; j < n; j++) {
                double distance = sampleLight(sr, light, j, strata);
                double g = light.G(sr) / light.pdf(sr);
                if (g > 0) {
                    addSample(sr, light, distance, g, 1.0 / n, n, L);
                }
            }
        }
    }

    /**
     * The book's loop body for the light sample in direction sr.wi, {@code distance} away: adds
     * f L g cos(theta_i) {@code weight} to {@code L} unless the light is behind the surface or a
     * shadow ray finds an occluder; g is G / pdf, {@code weight} 1 / samples and {@code samples}
     * the light's sample count at this hit. The unshadowed contribution is computed first: when it
     * could not change the pixel by the cutoff (Hall and Greenberg 1983), the shadow ray is not
     * traced and the sample is left out.
     */
    private void addSample(ShadeRec sr, Light light, double distance, double g, double weight, int samples, MutableRgb L) {
        MutableVec3 wi = sr.wi;
        double nDotWi = sr.normal.dot(wi);
        // the geometric normal decides which side the light is on, so bumped normals do not leak
        if (nDotWi <= 0 || sr.geometricNormal.dot(wi) <= 0) {
            return;
        }
        MutableRgb f = reflectance(sr, light, g, samples, nDotWi);
        MutableRgb incident = sr.scratch.lightScratch;
        light.L(sr, incident);
        if (negligible(sr, f, incident, g) || shadowed(sr, light, distance)) {
            return;
        }
        L.addProduct(f, incident, g * weight);
    }

    /**
     * Sets sr.wo and writes the ambient term rho_a La into {@code L}; false, with {@code L}
     * black, when the pass hides this hit's direct light.
     */
    private boolean ambient(ShadeRec sr, MutableRgb L) {
        WorkerScratch scratch = sr.scratch;
        MutableVec3 wo = sr.wo.set(-sr.ray.dx, -sr.ray.dy, -sr.ray.dz).normalize();
        if (!scratch.policy.showsDirect(sr.depth)) {
            L.setBlack();
            return false;
        }
        if (ambientZero) {
            scratch.skipped[Skipped.AMBIENT_TERMS]++;
            L.setBlack();
            return true;
        }
        MutableRgb f = scratch.brdfScratch;
        MutableRgb incident = scratch.lightScratch;
        ambient.rho(sr, wo, f);
        sr.world.ambient().L(sr, incident);
        L.setBlack().addProduct(f, incident, 1);
        return true;
    }

    /** How many samples of the light's dimension a pixel spreads its hits' samples across: the light's full count as the sampler rounds it. */
    private static int strata(ShadeRec sr, Light light) {
        return light.hasExtent() ? sr.world.viewPlane().sampler().supportedCount(light.sampleCount()) : 1;
    }

    /**
     * Writes the direction of light sample {@code j} into sr.wi and returns the distance to it: the
     * light's one direction, or, for a light with extent, the point of its surface that the pixel's
     * sample values of the light's dimension pick ({@code strata} of them across the pixel).
     */
    private static double sampleLight(ShadeRec sr, Light light, int j, int strata) {
        if (!light.hasExtent()) {
            return light.getDirection(sr, sr.wi);
        }
        PixelSamples samples = sr.scratch.samples;
        samples.get2D(sr.depth, PixelSamples.LIGHT + light.number(), j, strata);
        return light.sample(sr, samples.u, samples.v, sr.wi);
    }

    /** How many samples of {@code light} a hit draws: one without extent, else the ray tree's count at its depth as the sampler rounds it. */
    private static int samplesAt(ShadeRec sr, Light light) {
        if (!light.hasExtent()) {
            return 1;
        }
        return sr.world.viewPlane().sampler().supportedCount(sr.scratch.policy.lightSamples(sr.depth, light.sampleCount()));
    }

    /**
     * The BRDF's factor for the sample in direction sr.wi, in the worker's BRDF scratch:
     * f cos(theta_i) with f the diffuse term plus the specular lobe, or the report's variant
     * ({@link LightingTerms}). 1 / g is the sample's density over solid angle, for a glossy lobe's weight.
     */
    private MutableRgb reflectance(ShadeRec sr, Light light, double g, int samples, double nDotWi) {
        MutableRgb f = sr.scratch.brdfScratch;
        if (diffuseZero) {
            sr.scratch.skipped[Skipped.DIFFUSE_TERMS]++;
            f.setBlack();
        } else {
            diffuse.f(sr, sr.wo, sr.wi, f);
        }
        terms.combine(f, lobe(sr, light, g, samples), nDotWi);
        return f;
    }

    /**
     * The specular lobe's value f_s for the sample, in the worker's specular scratch, or null
     * without a lobe (or with one that is zero at every hit, counted): a glossy reflector's weighed
     * against its glossy rays for a light with extent ({@link GlossyLightMis}).
     */
    private MutableRgb lobe(ShadeRec sr, Light light, double g, int samples) {
        if (specular == null) {
            return null;
        }
        if (specularZero) {
            sr.scratch.skipped[Skipped.SPECULAR_LOBES]++;
            return null;
        }
        MutableRgb fs = sr.scratch.specularScratch;
        if (mis != null && light.hasExtent()) {
            mis.weightedLobe(sr, light, 1 / g, samples, fs);
        } else {
            specular.f(sr, sr.wo, sr.wi, fs);
        }
        return fs;
    }

    /**
     * True when the sample's f L g, its estimate of the light's whole contribution, could not change
     * the pixel by the cutoff (Hall and Greenberg 1983): one left out loses less than cutoff /
     * samples, so a hit loses less than the cutoff per light.
     */
    private static boolean negligible(ShadeRec sr, MutableRgb f, MutableRgb incident, double g) {
        return sr.scratch.policy.negligible(sr.depth, f.r * incident.r * g, f.g * incident.g * g, f.b * incident.b * g);
    }

    /**
     * True when something blocks the light ({@link Light#inShadow}); a light whose shadow rays the
     * scene analysis proved unblockable traces none, and counts it.
     */
    private static boolean shadowed(ShadeRec sr, Light light, double distance) {
        if (light.castsShadows()) {
            return light.inShadow(sr, distance);
        }
        if (light.shadowRaysLeftOut()) {
            sr.scratch.skipped[Skipped.SHADOW_RAYS]++;
        }
        return false;
    }

    /**
     * Counts the light samples a dark surface (no term reflects direct light) does not draw: one per
     * light from its direction, or, by area_light_shade, those of each light that could reach it.
     */
    private static void countUnlit(ShadeRec sr, boolean areaLights) {
        long[] skipped = sr.scratch.skipped;
        for (Light light : sr.world.lights()) {
            if (!areaLights) {
                skipped[Skipped.LIGHT_SAMPLES]++;
            } else if (light.mayIlluminate(sr)) {
                // nothing to draw: each sample value is a function of its index, so no later one moves
                skipped[Skipped.LIGHT_SAMPLES] += samplesAt(sr, light);
            }
        }
    }

    /**
     * How many samples of {@code light} this hit draws whose lobe term covers direction
     * {@code wi}: the light's count at this depth when the hit shows direct light, reflects it with
     * a specular lobe and the light can reach it from wi (in front of both normals); else 0. A
     * glossy ray that finds the light's surface in direction wi weighs its radiance against them.
     */
    int lightSamplesToward(ShadeRec sr, Light light, MutableVec3 wi) {
        if (dark || specular == null || specularZero || !sr.scratch.policy.showsDirect(sr.depth) || !light.hasExtent()
            || !(sr.normal.dot(wi) > 0) || !(sr.geometricNormal.dot(wi) > 0) || !light.mayIlluminate(sr)) {
            return 0;
        }
        for (Light l : sr.world.lights()) {
            if (l == light) {
                return samplesAt(sr, light);
            }
        }
        return 0;
    }

    /**
     * This lighting without the terms that are zero at every hit of {@code world}'s render (ka,
     * kd or ks of 0, or an ambient light of zero radiance) and with constant textures read as
     * colours; what was left out is added to {@code skips}, named for {@code material}.
     */
    DirectLighting simplified(World world, String material, List<Skip> skips) {
        String of = "material '" + material + "'";
        BRDF a = ambient.simplified();
        BRDF d = diffuse.simplified();
        BRDF s = specular == null ? null : specular.simplified();
        if (a != ambient || d != diffuse || s != specular) {
            skips.add(new Skip(Skipped.UNCOUNTED, "constant texture read as a plain colour", of));
        }
        boolean noAmbient = ambientZero || world.ambient().isBlack() || a.isBlack();
        boolean noDiffuse = diffuseZero || d.isBlack();
        boolean noSpecular = specularZero || s != null && s.isBlack();
        DirectLighting result = new DirectLighting(a, d, s, terms, mis, noAmbient, noDiffuse, noSpecular);
        if (noAmbient && !ambientZero) {
            skips.add(new Skip(Skipped.AMBIENT_TERMS, "ambient term not evaluated",
                               of + (a.isBlack() ? ": its ambient reflectance is 0" : ": the ambient light is black")));
        }
        if (result.dark && !dark) {
            skips.add(new Skip(Skipped.LIGHT_SAMPLES, "lights not evaluated, no shadow rays",
                               of + ": no term reflects direct light"));
        } else if (!result.dark) {
            if (noDiffuse && !diffuseZero) {
                skips.add(new Skip(Skipped.DIFFUSE_TERMS, "diffuse term not evaluated", of + ": its diffuse reflectance is 0"));
            }
            if (noSpecular && !specularZero) {
                skips.add(new Skip(Skipped.SPECULAR_LOBES, "specular lobe not evaluated", of + ": its specular reflectance is 0"));
            }
        }
        return result;
    }
}
