package raytracer.core;

import java.util.List;
import java.util.Locale;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Ray;

/**
 * Something a ray can hit (Suffern, chapter 19). Hits are two-phase: {@link #hit} finds the
 * distance and records it, {@link #completeHit} computes the shading data once for the winner.
 */
public abstract class GeometricObject {
    private Material material;
    private boolean castsShadows = true;

    /**
     * Looks for a hit with 0 &lt; t &lt; {@code sr.t}; if found, records it with
     * {@link ShadeRec#recordHit} (and what completion needs) and returns true.
     */
    public abstract boolean hit(Ray ray, ShadeRec sr);

    /**
     * True when the ray hits this object at some 0 &lt; t &lt; {@code tMax}. Nothing is recorded:
     * {@code sr} only lends scratch rays to instances.
     */
    public abstract boolean shadowHit(Ray ray, double tMax, ShadeRec sr);

    /**
     * For the hit recorded in {@code sr} along {@code ray} (in this object's space): writes
     * {@code sr.hitPoint}, {@code sr.hitError}, {@code sr.normal}, {@code sr.geometricNormal}
     * (outward, any length) and {@code sr.u}, {@code sr.v}.
     */
    public abstract void completeHit(Ray ray, ShadeRec sr);

    /** A box around the object; unbounded objects (planes) return an infinite box. */
    public abstract BBox boundingBox();

    /** The end of most {@code hit} methods: records t for this leaf when it beats the closest hit so far. */
    protected final boolean recordIfCloser(double t, ShadeRec sr) {
        if (t < sr.t) {
            sr.recordHit(t, this);
            return true;
        }
        return false;
    }

    /**
     * Whether shading a hit on this object may read its u, v: its material's answer, and true
     * without a material (an aggregate, whose leaves carry their own).
     */
    public boolean usesTextureCoordinates() {
        return material == null || material.needs().textureCoordinates();
    }

    public Material getMaterial() {
        return material;
    }

    public void setMaterial(Material material) {
        this.material = material;
    }

    public boolean castsShadows() {
        return castsShadows;
    }

    public void setCastsShadows(boolean castsShadows) {
        this.castsShadows = castsShadows;
    }

    /**
     * The object as it is rendered, made once by {@link World#prepare} for each object the scene
     * analysis kept: a mesh read from a file builds its BVH here, so that a mesh left out is never
     * built. Most objects are ready as they are and return themselves.
     */
    public GeometricObject prepared() {
        return this;
    }

    /**
     * Every material a hit on this object can be shaded with (a mesh's per-face materials too),
     * for the scene analysis.
     */
    public List<Material> materials() {
        return material == null ? List.of() : List.of(material);
    }

    /**
     * True when no shadow ray that leaves a point of this surface towards a light on its lit side
     * (the side the geometric normal, turned to the viewer, points to) can hit the object again:
     * a plane, or the closed surface of a convex solid seen from outside ({@link #isClosed}). It
     * must hold in floating point too, where the ray's origin is offset by the hit point's error
     * bound ({@link ShadeRec#spawnRay}).
     */
    public boolean cannotShadowItself() {
        return false;
    }

    /**
     * True when the surface encloses a solid: seen from inside, its lit side faces inwards and it
     * does shadow itself, so {@link #cannotShadowItself} holds only while no ray starts inside it.
     */
    public boolean isClosed() {
        return false;
    }

    /**
     * This object as rays that stay in {@code volume} (the half-spaces of a tile's camera rays) can
     * hit it: null when none can (the volume wholly excludes its box), else the object itself, or
     * an aggregate's view of it that searches only what such rays can reach. A hit on the view is
     * recorded as the aggregate's, or its leaf's, as before.
     */
    public GeometricObject within(List<HalfSpace> volume) {
        BBox box = boundingBox();
        for (HalfSpace face : volume) {
            if (face.excludes(box)) {
                return null;
            }
        }
        return this;
    }

    /**
     * The plane this object is, when it is a whole plane that every ray crossing it hits (an
     * unbounded surface with no hole), as the half-space n . p &lt;= d on one of its sides; null for
     * anything else. For the scene analysis: what lies beyond such a plane cannot be seen or light
     * what is seen, unless its material lets rays through.
     */
    public HalfSpace wholePlane() {
        return null;
    }

    /** What the object is, for messages ("sphere", "mesh dragon.obj"). */
    public String description() {
        return getClass().getSimpleName().toLowerCase(Locale.ROOT);
    }
}
