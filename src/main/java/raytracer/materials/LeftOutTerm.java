package raytracer.materials;

import raytracer.core.BRDF;
import raytracer.core.ShadeRec;
import raytracer.math.MutableRgb;
import raytracer.math.MutableVec3;

/**
 * A term the scene analysis proved zero at every hit (a kd or ks of 0), put in its place: black,
 * and counted as left out ({@link raytracer.core.Skipped}) each time the lighting asks for it.
 */
final class LeftOutTerm implements BRDF {
    private final int counter;

    LeftOutTerm(int counter) {
        this.counter = counter;
    }

    @Override
    public void f(ShadeRec sr, MutableVec3 wo, MutableVec3 wi, MutableRgb out) {
        sr.scratch.skipped[counter]++;
        out.setBlack();
    }

    @Override
    public void rho(ShadeRec sr, MutableVec3 wo, MutableRgb out) {
        sr.scratch.skipped[counter]++;
        out.setBlack();
    }

    @Override
    public boolean isBlack() {
        return true;
    }
}
