package raytracer.lights;

import java.util.List;
import raytracer.math.BBox;
import raytracer.math.MutableVec3;

/**
 * The surface of an area light and how its points are sampled as seen from a shaded point: by
 * area, or by the solid angle the surface covers there.
 */
interface Emitter {

    /**
     * Writes the point for (u, v) in [0,1)^2, as seen from {@code p}, and the unit normal on its
     * emitting side; returns the density of that choice over the emitter's area, positive. The map
     * is continuous and preserves measure (area or solid angle), so stratified (u, v) give
     * stratified points.
     */
    double sample(MutableVec3 p, double u, double v, MutableVec3 point, MutableVec3 normal);

    /**
     * The density over the emitter's area with which {@link #sample} from ({@code px}, {@code py},
     * {@code pz}) picks a point {@code distance} away, seen at {@code cosLight} from its normal.
     */
    double pdf(double px, double py, double pz, double distance, double cosLight);

    double area();

    /**
     * Moves {@code point}, written by {@link #sample} with {@code normal}, off the emitter along the
     * normal, to the emitting side, beyond every point within the sample's rounding of the exact
     * surface the scene describes (and beyond the rounding of the move itself): a shadow ray that
     * ends there ends short of any surface in the emitter's plane.
     */
    void moveOff(MutableVec3 point, MutableVec3 normal);

    /** A box around every point of the emitter. */
    /** Chooses how to draw samples for a frame whose lit objects lie in {@code receivers} ({@link raytracer.core.Light#prepare}). */
    default void prepare(List<BBox> receivers) {
    }

    BBox bounds();

    /**
     * False only when no point of the emitter can light point {@code p} of a surface with unit
     * normal {@code n}: p is behind the emitting side, or the whole emitter lies below p's tangent
     * plane. Conservative: true may still mean that every sample weighs nothing.
     */
    boolean mayLight(MutableVec3 p, MutableVec3 n);

    /**
     * G = cos(theta_light) / d^2 of the point {@code q} with unit normal {@code n} seen from
     * {@code p} (Suffern, chapter 18); 0 when it faces away. {@link AreaLight#G} and the emitters
     * that sample by solid angle take it from here, so that a sample's G and its area density
     * pdf_omega G agree to the last bit and G / pdf is 1 / pdf_omega.
     */
    static double geometricFactor(MutableVec3 p, MutableVec3 q, MutableVec3 n) {
        double dx = q.x - p.x;
        double dy = q.y - p.y;
        double dz = q.z - p.z;
        double d2 = dx * dx + dy * dy + dz * dz;
        double cosLight = -(n.x * dx + n.y * dy + n.z * dz) / Math.sqrt(d2);
        return cosLight > 0 ? cosLight / d2 : 0;
    }
}
