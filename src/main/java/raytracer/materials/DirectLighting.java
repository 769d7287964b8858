package raytracer.materials;

import raytracer.core.BRDF;
import raytracer.core.Light;
import raytracer.core.ShadeRec;
import raytracer.core.WorkerScratch;
import raytracer.math.Ray;
import raytracer.math.Rgb;
import raytracer.math.Vec3;

/**
 * The direct-lighting sum shared by Matte, Phong and Reflective (Suffern, listing 14.13):
 * L = rho_a La + sum over lights of (f_d + f_s) L_i (n . wi), each light skipped when it is behind
 * the surface or a shadow ray finds an occluder.
 */
final class DirectLighting {
    private DirectLighting() {
    }

    /** Writes the reflected direct radiance into {@code out}; {@code specular} may be null. */
    static void shade(ShadeRec sr, BRDF ambient, BRDF diffuse, BRDF specular, Rgb out) {
        shade(sr, ambient, diffuse, specular, false, out);
    }

    /**
     * As above; {@code seedCompatible} reproduces the report's two quirks (brdf-params.md): the
     * diffuse term without its 1/pi and the specular term without cos(theta_i).
     */
    static void shade(ShadeRec sr, BRDF ambient, BRDF diffuse, BRDF specular, boolean seedCompatible, Rgb out) {
        shade(sr, ambient, diffuse, specular, seedCompatible, true, out);
    }

    /**
     * As above; without {@code specularFromAreaLights} area lights add only their diffuse term,
     * for materials whose traced glossy rays already find the lights' surfaces (SPEC section 2).
     */
    static void shade(ShadeRec sr, BRDF ambient, BRDF diffuse, BRDF specular, boolean seedCompatible,
                      boolean specularFromAreaLights, Rgb out) {
        WorkerScratch scratch = sr.scratch;
        Vec3 wo = sr.wo.set(-sr.ray.dx, -sr.ray.dy, -sr.ray.dz).normalize();
        if (!sr.world.pass().direct(sr.depth)) {
            out.setBlack();
            return;
        }
        Rgb f = scratch.brdfScratch;
        Rgb incident = scratch.lightScratch;

        ambient.rho(sr, wo, f);
        sr.world.ambient().L(sr, incident);
        out.setBlack().addProduct(f, incident, 1);

        Vec3 wi = sr.wi;
        for (Light light : sr.world.lights()) {
            int n = light.sampleCount();
            boolean sampled = light.hasExtent();
            if (sampled && !light.mayIlluminate(sr)) {
                continue; // every sample would weigh nothing: draw none
            }
            if (sampled) {
                // a fresh stratified pattern per light and point (Suffern, section 18.5)
                n = sr.world.viewPlane().sampler().supportedCount(scratch.lightSamples(sr.depth, n));
                sr.world.viewPlane().sampler().generate(n, scratch.rng, scratch.lightX, scratch.lightY);
            }
            for (int s = 0; s < n; s++) {
                double u = sampled ? scratch.lightX[s] : 0.5;
                double v = sampled ? scratch.lightY[s] : 0.5;
                BRDF lobe = sampled && !specularFromAreaLights ? null : specular;
                addSample(sr, light, light.sample(sr, u, v, wi), diffuse, lobe, seedCompatible, 1.0 / n, out);
            }
        }
    }

    /**
     * Adds one light sample in direction sr.wi, weighted by {@code weight} (1 / samples). The
     * unshadowed contribution is computed first: when it could not change the pixel by the world's
     * cutoff (Hall and Greenberg 1983), the shadow ray is not traced and the sample is left out.
     */
    private static void addSample(ShadeRec sr, Light light, double distance, BRDF diffuse, BRDF specular,
                                  boolean seedCompatible, double weight, Rgb out) {
        WorkerScratch scratch = sr.scratch;
        Vec3 wi = sr.wi;
        double nDotWi = sr.normal.dot(wi);
        // the geometric normal decides which side the light is on, so bumped normals do not leak
        if (nDotWi <= 0 || sr.geometricNormal.dot(wi) <= 0) {
            return;
        }
        double g = light.geometryOverPdf(sr);
        if (!(g > 0)) {
            return;
        }
        Rgb f = scratch.brdfScratch;
        Rgb incident = scratch.lightScratch;
        diffuse.f(sr, sr.wo, wi, f);
        light.L(sr, incident);
        if (seedCompatible) {
            // the report's quirks: diffuse without 1/pi, specular without cos(theta_i)
            f.scale(Math.PI * nDotWi);
            if (specular != null) {
                Rgb fs = scratch.specularScratch;
                specular.f(sr, sr.wo, wi, fs);
                f.add(fs);
            }
        } else {
            if (specular != null) {
                Rgb fs = scratch.specularScratch;
                specular.f(sr, sr.wo, wi, fs);
                f.add(fs);
            }
            f.scale(nDotWi);
        }
        // f L g, with f now holding the factor that reaches the viewer, is this sample's estimate of
        // the light's whole contribution; one left out below the cutoff loses less than
        // cutoff / samples, so a hit loses less than the cutoff per light
        if (scratch.negligible(sr.depth, f.r * incident.r * g, f.g * incident.g * g, f.b * incident.b * g)) {
            return;
        }
        if (light.castsShadows()) {
            Ray shadowRay = sr.spawnRay(wi.x, wi.y, wi.z, scratch.shadowRay);
            if (light.inShadow(shadowRay, distance, sr)) {
                return;
            }
        }
        out.addProduct(f, incident, g * weight);
    }
}
