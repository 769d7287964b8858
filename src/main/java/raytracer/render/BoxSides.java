package raytracer.render;

import java.util.List;
import raytracer.core.Light;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;

/**
 * The scene analysis's proofs that boxes lie apart: an axis-aligned plane through a face of one
 * box with the other strictly beyond it. A box's six faces are the only planes tried, which is
 * enough for the cases that matter (a caster beside what it might shadow) and cheap to prove.
 */
final class BoxSides {
    private BoxSides() {
    }

    /**
     * True when an axis-aligned plane has the caster's box strictly on one side and the other
     * object's box and the light on the other: every shadow ray from the other object to the
     * light then stays on that side.
     */
    static boolean separated(BBox caster, BBox other, Light light) {
        for (HalfSpace h : sides(other)) {
            if (h.excludes(caster) && light.keepsShadowRaysWithin(h)) {
                return true;
            }
        }
        return false;
    }

    /** True when an axis-aligned plane has box {@code a} strictly on one side and box {@code b} on the other. */
    static boolean separated(BBox a, BBox b) {
        for (HalfSpace h : sides(b)) {
            if (h.excludes(a)) {
                return true;
            }
        }
        return false;
    }

    /** The six half-spaces bounded by the faces of a box, each holding the box; none for an unbounded box. */
    private static List<HalfSpace> sides(BBox box) {
        if (!box.isBounded()) {
            return List.of();
        }
        return List.of(new HalfSpace(-1, 0, 0, -box.x0()), new HalfSpace(1, 0, 0, box.x1()),
                       new HalfSpace(0, -1, 0, -box.y0()), new HalfSpace(0, 1, 0, box.y1()),
                       new HalfSpace(0, 0, -1, -box.z0()), new HalfSpace(0, 0, 1, box.z1()));
    }
}
