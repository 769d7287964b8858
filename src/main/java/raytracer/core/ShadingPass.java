package raytracer.core;

import java.util.Locale;

/**
 * The report's term passes (figures 4 and 6): which terms the first hit contributes. The magenta
 * pass is the full image except that the first hit's reflected rays see pure magenta, as in the
 * report's figures 4c and 6c (the highlight and the refraction stay). Deeper hits
 * are always shaded in full, so "reflection only" shows everything the mirror reflects. The
 * ablation {@link #NO_FRESNEL} ignores the angle dependence at every depth: mirrors reflect their
 * normal-incidence fraction, glass refracts everything and reflects nothing.
 */
public enum ShadingPass {
    FULL, DIRECT, REFLECTION, REFRACTION, MAGENTA_REFLECTION, NO_FRESNEL;

    public boolean direct(int depth) {
        return depth > 0 || this == FULL || this == DIRECT || this == MAGENTA_REFLECTION || this == NO_FRESNEL;
    }

    public boolean reflection(int depth) {
        return depth > 0 || this == FULL || this == REFLECTION || this == MAGENTA_REFLECTION || this == NO_FRESNEL;
    }

    public boolean refraction(int depth) {
        return depth > 0 || this == FULL || this == REFRACTION || this == MAGENTA_REFLECTION || this == NO_FRESNEL;
    }

    /** Reflected rays of the first hit see a pure magenta environment, to show the reflected fraction. */
    public boolean magentaReflection(int depth) {
        return depth == 0 && this == MAGENTA_REFLECTION;
    }

    public boolean angleDependent() {
        return this != NO_FRESNEL;
    }

    public String key() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    public static ShadingPass parse(String text) {
        for (ShadingPass p : values()) {
            if (p.key().equals(text)) {
                return p;
            }
        }
        throw new IllegalArgumentException("unknown pass '" + text
            + "'; allowed: full, direct, reflection, refraction, magenta-reflection, no-fresnel");
    }
}
