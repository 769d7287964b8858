package raytracer.materials;

import java.util.List;
import raytracer.core.BRDF;
import raytracer.core.Light;
import raytracer.core.PixelSamples;
import raytracer.core.RayTreePolicy;
import raytracer.core.Sampler;
import raytracer.core.ShadeRec;
import raytracer.core.Skip;
import raytracer.core.Skipped;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * The direct light of a lit material, ambient plus a diffuse and an optional specular lobe, in the
 * book's two forms: {@link #shade} takes each light from its one direction (Suffern, chapters 14
 * and 15: L = rho_a La + sum over lights of f L cos(theta_i)), {@link #areaLightShade} averages
 * each light's samples (chapter 18: f L G cos(theta_i) / pdf, with G = pdf = 1 for lights without
 * extent, so both give the same for them). A light is skipped when it is behind the surface or a
 * shadow ray finds an occluder. {@link #simplified} leaves out the terms that are zero at every
 * hit; each would have added +0, so the image is the same to the bit.
 */
final class DirectLighting {

    /** Which lobes a light sample lights, and how. */
    enum Terms {
        /** (f_d + f_s) cos(theta_i), the integrand of the reflection equation. */
        PHYSICAL,
        /**
         * The report's quirks (docs/brdf-params.md), for its figure 2's brightness: f_d pi cos(theta_i)
         * + f_s, the diffuse term without its 1/pi and the specular one without cos(theta_i).
         */
        REPORT
    }

    private final BRDF ambient;
    private final BRDF diffuse;
    private final BRDF specular;
    private final Terms terms;
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
    DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular, Terms terms) {
        this(ambient, diffuse, specular, terms, null, false, false, false);
    }

    DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular) {
        this(ambient, diffuse, specular, Terms.PHYSICAL);
    }

    /** The direct light of a glossy reflector, whose glossy rays also find visible area lights ({@link GlossyLightMis}). */
    DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular, GlossyLightMis mis) {
        this(ambient, diffuse, specular, Terms.PHYSICAL, mis, false, false, false);
    }

    private DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular, Terms terms, GlossyLightMis mis, boolean ambientZero,
                           boolean diffuseZero, boolean specularZero) {
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

    /** Suffern's shade: writes into {@code out} the ambient term plus each light's, from its one direction. */
    void shade(ShadeRec sr, MutableRgb out) {
        if (!ambient(sr, out)) {
            return;
        }
        if (dark) {
            sr.scratch.skipped[Skipped.LIGHT_SAMPLES] += sr.world.lights().length;
            return;
        }
        for (Light light : sr.world.lights()) {
            addSample(sr, light, light.getDirection(sr, sr.wi), specular, 1, 1, 1, out);
        }
    }

    /**
     * Suffern's area_light_shade: writes into {@code out} the ambient term plus, for each light, the
     * average over its samples of f L G cos(theta_i) / pdf (one sample for lights without extent).
     * A light with extent takes the values of its dimension, stratified across the pixel's samples
     * ({@link PixelSamples}), as many as the ray tree's policy gives a hit at this depth.
     */
    void areaLightShade(ShadeRec sr, MutableRgb out) {
        if (!ambient(sr, out)) {
            return;
        }
        WorkerScratch scratch = sr.scratch;
        PixelSamples samples = scratch.samples;
        MutableVec3 wi = sr.wi;
        for (Light light : sr.world.lights()) {
            if (!light.mayIlluminate(sr)) {
                continue; // every sample would weigh nothing: draw none
            }
            if (!light.hasExtent()) {
                if (dark) {
                    scratch.skipped[Skipped.LIGHT_SAMPLES]++;
                } else {
                    addSample(sr, light, light.getDirection(sr, wi), specular, 1, 1, 1, out);
                }
                continue;
            }
            Sampler sampler = sr.world.viewPlane().sampler();
            int most = sampler.supportedCount(light.sampleCount());
            int n = sampler.supportedCount(scratch.policy.lightSamples(sr.depth, light.sampleCount()));
            if (dark) {
                // nothing to draw: each sample value is a function of its index, so no later one moves
                scratch.skipped[Skipped.LIGHT_SAMPLES] += n;
                continue;
            }
            for (int s = 0; s < n; s++) {
                samples.get2D(sr.depth, PixelSamples.LIGHT + light.number(), s, most);
                double distance = light.sample(sr, samples.u, samples.v, wi);
                double g = light.G(sr) / light.pdf(sr);
                if (g > 0) {
                    addSample(sr, light, distance, specular, g, 1.0 / n, n, out);
                }
            }
        }
    }

    /**
     * Sets sr.wo and writes the ambient term rho_a La into {@code out}; false, with {@code out}
     * black, when the pass hides this hit's direct light.
     */
    private boolean ambient(ShadeRec sr, MutableRgb out) {
        WorkerScratch scratch = sr.scratch;
        MutableVec3 wo = sr.wo.set(-sr.ray.dx, -sr.ray.dy, -sr.ray.dz).normalize();
        if (!scratch.policy.showsDirect(sr.depth)) {
            out.setBlack();
            return false;
        }
        if (ambientZero) {
            scratch.skipped[Skipped.AMBIENT_TERMS]++;
            out.setBlack();
            return true;
        }
        MutableRgb f = scratch.brdfScratch;
        MutableRgb incident = scratch.lightScratch;
        ambient.rho(sr, wo, f);
        sr.world.ambient().L(sr, incident);
        out.setBlack().addProduct(f, incident, 1);
        return true;
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
                Sampler sampler = sr.world.viewPlane().sampler();
                return sampler.supportedCount(sr.scratch.policy.lightSamples(sr.depth, light.sampleCount()));
            }
        }
        return 0;
    }

    /**
     * Adds f L g cos(theta_i) {@code weight} for the light sample in direction sr.wi, where g is
     * G / pdf, {@code weight} 1 / samples and {@code samples} the light's sample count at this hit.
     * The unshadowed contribution is computed first: when it could not change the pixel by the
     * cutoff (Hall and Greenberg 1983), the shadow ray is not traced and the sample is left out.
     */
    private void addSample(ShadeRec sr, Light light, double distance, BRDF lobe, double g, double weight, int samples,
                           MutableRgb out) {
        WorkerScratch scratch = sr.scratch;
        MutableVec3 wi = sr.wi;
        double nDotWi = sr.normal.dot(wi);
        // the geometric normal decides which side the light is on, so bumped normals do not leak
        if (nDotWi <= 0 || sr.geometricNormal.dot(wi) <= 0) {
            return;
        }
        MutableRgb f = scratch.brdfScratch;
        MutableRgb incident = scratch.lightScratch;
        if (diffuseZero) {
            scratch.skipped[Skipped.DIFFUSE_TERMS]++;
            f.setBlack();
        } else {
            diffuse.f(sr, sr.wo, wi, f);
        }
        light.L(sr, incident);
        if (terms == Terms.REPORT) {
            f.scale(Math.PI * nDotWi);
            addLobe(sr, light, lobe, g, samples, f);
        } else {
            addLobe(sr, light, lobe, g, samples, f);
            f.scale(nDotWi);
        }
        // f L g, with f now holding the factor that reaches the viewer, is this sample's estimate of
        // the light's whole contribution; one left out below the cutoff loses less than
        // cutoff / samples, so a hit loses less than the cutoff per light
        RayTreePolicy policy = scratch.policy;
        if (policy.negligible(sr.depth, f.r * incident.r * g, f.g * incident.g * g, f.b * incident.b * g)) {
            return;
        }
        if (light.castsShadows()) {
            if (light.inShadow(sr, distance)) {
                return;
            }
        } else if (light.shadowRaysLeftOut()) {
            scratch.skipped[Skipped.SHADOW_RAYS]++;
        }
        out.addProduct(f, incident, g * weight);
    }

    /**
     * Adds the lobe's value for the sample to f: a glossy reflector's weighed against its glossy
     * rays for a light with extent ({@link GlossyLightMis}; 1 / g is the sample's density over
     * solid angle, {@code samples} the light's count at this hit).
     */
    private void addLobe(ShadeRec sr, Light light, BRDF lobe, double g, int samples, MutableRgb f) {
        if (lobe != null && specularZero) {
            sr.scratch.skipped[Skipped.SPECULAR_LOBES]++;
        } else if (lobe != null) {
            MutableRgb fs = sr.scratch.specularScratch;
            if (mis != null && light.hasExtent()) {
                mis.weightedLobe(sr, light, 1 / g, samples, fs);
            } else {
                lobe.f(sr, sr.wo, sr.wi, fs);
            }
            f.add(fs);
        }
    }
}
