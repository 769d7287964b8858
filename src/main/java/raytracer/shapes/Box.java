package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Rounding;

/**
 * An axis-aligned box between two corners (Suffern, section 19.5), hit by the slab test. Completion
 * finds the face (0..2 for -x, -y, -z, 3..5 for +x, +y, +z) whose slab gave the hit's distance.
 */
public final class Box extends GeometricObject {
    private final double x0;
    private final double y0;
    private final double z0;
    private final double x1;
    private final double y1;
    private final double z1;

    public Box(Point3D p0, Point3D p1) {
        if (!p0.isFinite() || !p1.isFinite()) {
            throw new IllegalArgumentException("box corners must be finite");
        }
        x0 = Math.min(p0.x(), p1.x());
        y0 = Math.min(p0.y(), p1.y());
        z0 = Math.min(p0.z(), p1.z());
        x1 = Math.max(p0.x(), p1.x());
        y1 = Math.max(p0.y(), p1.y());
        z1 = Math.max(p0.z(), p1.z());
        if (!(x1 > x0 && y1 > y0 && z1 > z0)) {
            throw new IllegalArgumentException("a box needs a positive size along every axis");
        }
    }

    /** The first slab-test distance in (0, tMax): the entry, or the exit from inside; else +infinity. */
    private double slabs(Ray ray, double tMax) {
        double invDx = 1.0 / ray.dx;
        double invDy = 1.0 / ray.dy;
        double invDz = 1.0 / ray.dz;
        double txNear = ((invDx >= 0 ? x0 : x1) - ray.ox) * invDx;
        double txFar = ((invDx >= 0 ? x1 : x0) - ray.ox) * invDx;
        double tyNear = ((invDy >= 0 ? y0 : y1) - ray.oy) * invDy;
        double tyFar = ((invDy >= 0 ? y1 : y0) - ray.oy) * invDy;
        double tzNear = ((invDz >= 0 ? z0 : z1) - ray.oz) * invDz;
        double tzFar = ((invDz >= 0 ? z1 : z0) - ray.oz) * invDz;
        double tNear = Math.max(txNear, Math.max(tyNear, tzNear));
        double tFar = Math.min(txFar, Math.min(tyFar, tzFar));
        if (!(tNear < tFar)) {
            return Double.POSITIVE_INFINITY;
        }
        if (tNear > 0 && tNear < tMax) {
            return tNear;
        }
        if (tFar > 0 && tFar < tMax) {
            return tFar;
        }
        return Double.POSITIVE_INFINITY;
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return recordIfCloser(slabs(ray, sr.t), sr);
    }

    /**
     * True when the ray certainly enters or leaves the box strictly between its ends. Each slab
     * distance (b - o_k) / d_k is off by at most gamma(3) of itself, and the ray's own errors move
     * it by (originError + t directionError) / |d_k|: a face through the light's point touches the
     * shadow ray's end and does not block it.
     */
    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        double invDx = 1.0 / ray.dx;
        double invDy = 1.0 / ray.dy;
        double invDz = 1.0 / ray.dz;
        double txNear = ((invDx >= 0 ? x0 : x1) - ray.ox) * invDx;
        double txFar = ((invDx >= 0 ? x1 : x0) - ray.ox) * invDx;
        double tyNear = ((invDy >= 0 ? y0 : y1) - ray.oy) * invDy;
        double tyFar = ((invDy >= 0 ? y1 : y0) - ray.oy) * invDy;
        double tzNear = ((invDz >= 0 ? z0 : z1) - ray.oz) * invDz;
        double tzFar = ((invDz >= 0 ? z1 : z0) - ray.oz) * invDz;
        double tNear = Math.max(txNear, Math.max(tyNear, tzNear));
        double tFar = Math.min(txFar, Math.min(tyFar, tzFar));
        if (!(tNear < tFar)) {
            return false;
        }
        if (tNear > 0 && tFar < tMax) {
            return true; // through the box between the ends: the usual shadow, whatever the rounding at either face
        }
        double dNear = tNear == txNear ? ray.dx : tNear == tyNear ? ray.dy : ray.dz;
        double dFar = tFar == txFar ? ray.dx : tFar == tyFar ? ray.dy : ray.dz;
        return certainlyWithin(ray, tNear, dNear, tMax) || certainlyWithin(ray, tFar, dFar, tMax);
    }

    private static boolean certainlyWithin(Ray ray, double t, double dk, double tMax) {
        double margin = Rounding.gamma(3) * Math.abs(t) + (ray.originError + Math.abs(t) * ray.directionError) / Math.abs(dk);
        return t - margin > 0 && tMax - t - margin > 0;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        double t = sr.t;
        double px = ray.atX(t);
        double py = ray.atY(t);
        double pz = ray.atZ(t);
        int face = slabFace(ray, t);
        double g = Rounding.gamma(3);
        double ex = g * (Math.abs(ray.ox) + Math.abs(t * ray.dx));
        double ey = g * (Math.abs(ray.oy) + Math.abs(t * ray.dy));
        double ez = g * (Math.abs(ray.oz) + Math.abs(t * ray.dz));
        // snap the hit point onto its face: along the face normal it is then exact
        switch (face) {
            case 0 -> { px = x0; ex = 0; sr.normal.set(-1, 0, 0); }
            case 1 -> { py = y0; ey = 0; sr.normal.set(0, -1, 0); }
            case 2 -> { pz = z0; ez = 0; sr.normal.set(0, 0, -1); }
            case 3 -> { px = x1; ex = 0; sr.normal.set(1, 0, 0); }
            case 4 -> { py = y1; ey = 0; sr.normal.set(0, 1, 0); }
            default -> { pz = z1; ez = 0; sr.normal.set(0, 0, 1); }
        }
        sr.hitPoint.set(px, py, pz);
        sr.hitError.set(ex, ey, ez);
        sr.geometricNormal.set(sr.normal);
        double fx = (px - x0) / (x1 - x0);
        double fy = (py - y0) / (y1 - y0);
        double fz = (pz - z0) / (z1 - z0);
        switch (face % 3) {
            case 0 -> { sr.u = fz; sr.v = fy; }
            case 1 -> { sr.u = fx; sr.v = fz; }
            default -> { sr.u = fx; sr.v = fy; }
        }
    }

    /**
     * The face whose slab gave t in {@link #slabs}: the entry plane of the axis whose near distance
     * is t, else the exit plane of the axis whose far distance is t. So a ray enters through a face
     * it moves into (n . d = -|d_k| &lt; 0) and leaves through one it moves out of, even within
     * rounding of an edge, where the face nearest the hit point may be one the ray runs along, with
     * n . d about 0 and of either sign (a ray entering there was taken as hitting a back face).
     * The nearest face answers only if t is no slab distance (the ray is the search's, so it is).
     */
    private int slabFace(Ray ray, double t) {
        for (int exit = 0; exit < 2; exit++) {
            for (int k = 0; k < 3; k++) {
                double o = k == 0 ? ray.ox : k == 1 ? ray.oy : ray.oz;
                double inv = 1.0 / (k == 0 ? ray.dx : k == 1 ? ray.dy : ray.dz);
                // the plane of this axis that slabs() enters by (exit: leaves by), computed as there
                boolean upper = (inv >= 0) == (exit == 1);
                double plane = k == 0 ? (upper ? x1 : x0) : k == 1 ? (upper ? y1 : y0) : (upper ? z1 : z0);
                if ((plane - o) * inv == t) {
                    return upper ? k + 3 : k;
                }
            }
        }
        return nearestFace(ray.atX(t), ray.atY(t), ray.atZ(t));
    }

    /** The face whose plane is closest to the point, relative to the box size on that axis. */
    private int nearestFace(double px, double py, double pz) {
        int best = 0;
        double bestDistance = Math.abs(px - x0) / (x1 - x0);
        for (int face = 1; face < 6; face++) {
            double distance = switch (face) {
                case 1 -> Math.abs(py - y0) / (y1 - y0);
                case 2 -> Math.abs(pz - z0) / (z1 - z0);
                case 3 -> Math.abs(px - x1) / (x1 - x0);
                case 4 -> Math.abs(py - y1) / (y1 - y0);
                default -> Math.abs(pz - z1) / (z1 - z0);
            };
            if (distance < bestDistance) {
                best = face;
                bestDistance = distance;
            }
        }
        return best;
    }

    @Override
    public BBox boundingBox() {
        return new BBox(x0, y0, z0, x1, y1, z1);
    }
}
