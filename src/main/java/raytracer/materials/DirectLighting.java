package raytracer.materials;

import raytracer.core.BRDF;
import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.core.WorkerScratch;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * The direct light of a lit material, ambient plus a diffuse and an optional specular lobe, in the
 * book's two forms: {@link #shade} takes each light from its one direction (Suffern's Matte::shade
 * and Phong::shade, sections 14.7 and 15.5: L = rho_a La + sum over lights of f L cos(theta_i)),
 * {@link #areaLightShade} averages each light's samples (chapter 18's area_light_shade:
 * f L G cos(theta_i) / pdf, with G = pdf = 1 for lights without extent, so both give the same for
 * them). {@link #addSample} is the body of the book's loop.
 *
 * <p>Beyond the book, one call each: the pass that hides a hit's direct light (the report's
 * figures 4 and 6), the report's variant of the terms ({@link LightingTerms}), a glossy lobe
 * weighed against the glossy rays that may find the same light ({@link GlossyLightMis}), and the
 * adaptive cutoff, which drops a sample too faint to change the pixel before its shadow ray.
 */
final class DirectLighting implements Lighting {
    /** Null for a surface without an ambient term. */
    final BRDF ambient;
    final BRDF diffuse;
    /** Null for a surface without a specular lobe (a matte one). */
    final BRDF specular;
    final LightingTerms terms;
    /** For a glossy reflector's lobe under lights with extent; else null. */
    final GlossyLightMis mis;

    DirectLighting(BRDF ambient, BRDF diffuse, BRDF specular, LightingTerms terms, GlossyLightMis mis) {
        this.ambient = ambient;
        this.diffuse = diffuse;
        this.specular = specular;
        this.terms = terms;
        this.mis = mis;
    }

    @Override
    public void shade(ShadeRec sr, MutableRgb L) {
        if (!ambient(sr, L)) {
            return;
        }
        for (Light light : sr.world.lights()) {
            double distance = light.getDirection(sr, sr.wi);
            addSample(sr, light, distance, 1, 1, 1, L);
        }
    }

    @Override
    public void areaLightShade(ShadeRec sr, MutableRgb L) {
        if (!ambient(sr, L)) {
            return;
        }
        for (Light light : sr.world.lights()) {
            if (!light.mayIlluminate(sr)) {
                continue; // every sample would weigh nothing: draw none
            }
            int n = LightSamples.count(sr, light);
            for (int j = 0; j < n; j++) {
                double distance = LightSamples.sample(sr, light, j);
                double g = light.G(sr) / light.pdf(sr);
                if (g > 0) {
                    addSample(sr, light, distance, g, 1.0 / n, n, L);
                }
            }
        }
    }

    /**
     * The book's loop body for the light sample in direction sr.wi, {@code distance} away: adds
     * f L g cos(theta_i) {@code weight} to {@code L} unless the light is behind the surface or in
     * shadow; g is G / pdf, {@code weight} 1 / samples, {@code samples} the light's count at this hit.
     */
    private void addSample(ShadeRec sr, Light light, double distance, double g, double weight, int samples, MutableRgb L) {
        MutableVec3 wi = sr.wi;
        double nDotWi = sr.normal.dot(wi);
        // the geometric normal decides which side the light is on, so bumped normals do not leak
        if (nDotWi <= 0 || sr.geometricNormal.dot(wi) <= 0) {
            return;
        }
        MutableRgb f = sr.scratch.brdfScratch;
        diffuse.f(sr, sr.wo, wi, f);
        terms.combine(f, lobe(sr, light, g, samples), nDotWi);
        MutableRgb incident = sr.scratch.lightScratch;
        light.L(sr, incident);
        // Hall and Greenberg's cutoff (1983): a sample too faint to change the pixel traces no shadow ray
        if (sr.scratch.policy.negligible(sr.depth, f.r * incident.r * g, f.g * incident.g * g, f.b * incident.b * g)
            || light.shadowed(sr, distance)) {
            return;
        }
        L.addProduct(f, incident, g * weight);
    }

    /**
     * Sets sr.wo and writes the ambient term rho_a La into {@code L}; false, with {@code L} black,
     * when the pass hides this hit's direct light.
     */
    private boolean ambient(ShadeRec sr, MutableRgb L) {
        WorkerScratch scratch = sr.scratch;
        MutableVec3 wo = sr.wo.set(-sr.ray.dx, -sr.ray.dy, -sr.ray.dz).normalize();
        L.setBlack();
        if (!scratch.policy.showsDirect(sr.depth)) {
            return false;
        }
        if (ambient != null) {
            ambient.rho(sr, wo, scratch.brdfScratch);
            sr.world.ambient().L(sr, scratch.lightScratch);
            L.addProduct(scratch.brdfScratch, scratch.lightScratch, 1);
        }
        return true;
    }

    /**
     * The specular lobe's f_s for the sample (null without a lobe); a glossy reflector's weighed
     * against its glossy rays under a light with extent, whose density 1 / g they need.
     */
    private MutableRgb lobe(ShadeRec sr, Light light, double g, int samples) {
        if (specular == null) {
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

    @Override
    public int lightSamplesToward(ShadeRec sr, Light light, MutableVec3 wi) {
        if (specular == null || !sr.scratch.policy.showsDirect(sr.depth) || !light.hasExtent() || !(sr.normal.dot(wi) > 0)
            || !(sr.geometricNormal.dot(wi) > 0) || !light.mayIlluminate(sr)) {
            return 0;
        }
        for (Light l : sr.world.lights()) {
            if (l == light) {
                return LightSamples.count(sr, light);
            }
        }
        return 0; // a light the analysis left out
    }
}
