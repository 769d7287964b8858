package raytracer.materials;

import java.util.List;
import raytracer.brdf.GlossySpecular;
import raytracer.brdf.PerfectSpecular;
import raytracer.core.PixelSamples;
import raytracer.core.RayTreePolicy;
import raytracer.core.ShadeRec;
import raytracer.core.ShadingNeeds;
import raytracer.core.Skip;
import raytracer.core.World;
import raytracer.math.Fresnel;
import raytracer.math.MutableRgb;
import raytracer.math.RGBColor;

/**
 * Phong shading plus a perfect mirror term (Suffern, section 24.3; area lights: chapter 18): the
 * radiance traced along the mirror direction, scaled by the mirror's weight kr cr, is added to
 * Phong's direct light. With {@code schlick} the reflected fraction grows towards grazing angles by
 * Schlick's Fresnel approximation with kr as the reflectance at normal incidence (report section
 * 3: the brown mirror sphere with 0.5); the mirror's weight is then cr alone.
 */
public final class Reflective extends Phong {
    private final PerfectSpecular mirror;
    private final double kr;
    private final boolean schlick;
    /** Set when the scene analysis proves the mirror's rays weigh 0: they are counted, not traced. */
    private LeftOutRays leftOut;

    public Reflective(double ka, double kd, RGBColor cd, double ks, RGBColor cs, double exp,
                      double kr, RGBColor cr, boolean schlick) {
        super(ka, kd, cd, new GlossySpecular(ks, cs, exp, false), null);
        this.kr = kr;
        this.schlick = schlick;
        this.mirror = new PerfectSpecular(schlick ? 1 : kr, cr);
    }

    /**
     * Adds the radiance along the mirror direction (Suffern's Reflective::shade), times the
     * mirror's weight kr cr and the Fresnel fraction; sr.wo is set by the direct light.
     */
    @Override
    void traceRays(ShadeRec sr, MutableRgb out) {
        if (leftOut != null) {
            leftOut.count(sr);
            return;
        }
        RayTreePolicy policy = sr.scratch.policy;
        if (sr.depth + 1 > sr.world.viewPlane().maxDepth() || !policy.showsReflection(sr.depth)) {
            return;
        }
        MutableRgb fr = sr.scratch.weight(sr.depth);
        mirror.sampleF(sr, sr.wo, 0, 0, sr.wi, fr);
        double fraction = schlick && policy.angleDependent() ? Fresnel.schlick(kr, sr.normal.dot(sr.wo)) : schlick ? kr : 1;
        if (policy.recordBranchWeight(sr.depth, fr.r * fraction, fr.g * fraction, fr.b * fraction)) {
            MutableRgb incoming = sr.scratch.color(sr.depth + 1);
            BranchRay.trace(sr, sr.wi, PixelSamples.REFLECTED, sr.scratch, incoming, policy.reflectedEnvironment(sr.depth, reflectionMap()));
            out.addProduct(incoming, fr, fraction);
        }
    }

    /** Mirror rays are traced unless the analysis left them out (a kr cr of 0: they are traced, of weight 0, until then). */
    @Override
    public ShadingNeeds needs() {
        return new ShadingNeeds(textured(), leftOut == null, false, false);
    }

    /** Besides the direct light's zero terms, the mirror's rays when its weight kr cr is 0 and rays may be dropped. */
    @Override
    public List<Skip> simplify(World world, boolean mayDropRays) {
        List<Skip> skips = super.simplify(world, mayDropRays);
        if (mirror.isBlack() && mayDropRays && leftOut == null) {
            leftOut = new LeftOutRays(world.viewPlane().maxDepth());
            skips.add(leftOut.skip("mirror rays", name(), "kr or its colour is 0"));
        }
        return skips;
    }

    public PerfectSpecular mirror() {
        return mirror;
    }

    /** Whether the reflected fraction follows Schlick's approximation (kr at normal incidence). */
    public boolean schlick() {
        return schlick;
    }
}
