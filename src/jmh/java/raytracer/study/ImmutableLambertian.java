package raytracer.study;

import raytracer.math.RGBColor;

/** Perfect diffuse reflection, f = kd cd / pi and rho = kd cd (Suffern, section 13.9), as new colours. */
record ImmutableLambertian(double kd, RGBColor cd) {

    RGBColor f() {
        return cd.scale(kd / Math.PI);
    }

    RGBColor rho() {
        return cd.scale(kd);
    }
}
