package raytracer.shapes;

import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.core.Skipped;
import raytracer.math.BBox;
import raytracer.math.Ray;
import raytracer.math.Rounding;

/**
 * A cylinder around the y axis between heights y0 and y1 (Suffern, section 19.6), open or closed by
 * two disk caps. Place it elsewhere with an {@link Instance}. The part hit is kept in
 * {@code sr.primitive}: {@link #SIDE}, {@link #BOTTOM} or {@link #TOP}.
 */
public final class Cylinder extends GeometricObject {
    static final int SIDE = 0;
    static final int BOTTOM = 1;
    static final int TOP = 2;

    private final double y0;
    private final double y1;
    private final double radius;
    private final boolean closed;

    public Cylinder(double y0, double y1, double radius, boolean closed) {
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("cylinder radius must be a positive number, got " + radius);
        }
        if (!(y1 > y0) || !Double.isFinite(y0) || !Double.isFinite(y1)) {
            throw new IllegalArgumentException("cylinder needs finite heights with y0 < y1, got " + y0 + ", " + y1);
        }
        this.y0 = y0;
        this.y1 = y1;
        this.radius = radius;
        this.closed = closed;
    }

    /** The nearest hit distance in (0, tMax) or +infinity; the part hit goes to {@code partSink.primitive}. */
    private double nearest(Ray ray, double tMax, ShadeRec partSink) {
        if (closed) {
            return nearestOnSolid(ray, tMax, partSink);
        }
        double t = nearestOnSide(ray, tMax);
        if (partSink != null && t < tMax) {
            partSink.primitive = SIDE;
        }
        return t;
    }

    /** The open cylinder: the side's nearer root within the heights, else its farther one. */
    private double nearestOnSide(Ray ray, double tMax) {
        // side: (ox + t dx)^2 + (oz + t dz)^2 = r^2, solved stably as for the sphere; a ray along
        // the axis (a = 0) or tangent to the side (discriminant 0) does not cross it: no hit
        double a = ray.dx * ray.dx + ray.dz * ray.dz;
        if (a > 0) {
            double halfB = ray.ox * ray.dx + ray.oz * ray.dz;
            double s = halfB / a;
            double lx = ray.ox - s * ray.dx;
            double lz = ray.oz - s * ray.dz;
            double discriminant = radius * radius - (lx * lx + lz * lz);
            if (discriminant > 0) {
                double c = ray.ox * ray.ox + ray.oz * ray.oz - radius * radius;
                double q = -halfB - Math.copySign(Math.sqrt(a * discriminant), halfB);
                double ta = q / a;
                double tb = c / q;
                double tNear = Math.min(ta, tb);
                double tFar = Math.max(ta, tb);
                if (tNear > 0 && tNear < tMax && withinHeight(ray.atY(tNear))) {
                    return tNear;
                } else if (tFar > 0 && tFar < tMax && withinHeight(ray.atY(tFar))) {
                    return tFar;
                }
            }
        }
        return Double.POSITIVE_INFINITY;
    }

    /**
     * The closed cylinder as the solid it bounds: the ray's interval inside the infinite cylinder
     * cut by its interval between the cap planes, as the box's slab test cuts three intervals
     * (Kay and Kajiya 1986). The ray enters where the later of the two starts and leaves where the
     * earlier of the two ends, so every entry is a front face and every exit a back face, also
     * through the rim, where testing the side's height and the caps' radius apart could let a ray
     * slip between them and see the inside of the wall from outside. A ray that only touches the
     * solid (tangent to the side, along it, or in a cap's plane) meets an empty interval: no hit.
     */
    private double nearestOnSolid(Ray ray, double tMax, ShadeRec partSink) {
        double sideIn = Double.NEGATIVE_INFINITY;
        double sideOut = Double.POSITIVE_INFINITY;
        double a = ray.dx * ray.dx + ray.dz * ray.dz;
        if (a > 0) {
            double halfB = ray.ox * ray.dx + ray.oz * ray.dz;
            double s = halfB / a;
            double lx = ray.ox - s * ray.dx;
            double lz = ray.oz - s * ray.dz;
            double discriminant = radius * radius - (lx * lx + lz * lz);
            if (!(discriminant > 0)) {
                return Double.POSITIVE_INFINITY;
            }
            double c = ray.ox * ray.ox + ray.oz * ray.oz - radius * radius;
            double q = -halfB - Math.copySign(Math.sqrt(a * discriminant), halfB);
            sideIn = Math.min(q / a, c / q);
            sideOut = Math.max(q / a, c / q);
        } else if (!(ray.ox * ray.ox + ray.oz * ray.oz < radius * radius)) {
            return Double.POSITIVE_INFINITY;
        }
        double capIn = Double.NEGATIVE_INFINITY;
        double capOut = Double.POSITIVE_INFINITY;
        if (ray.dy != 0) {
            double tBottom = (y0 - ray.oy) / ray.dy;
            double tTop = (y1 - ray.oy) / ray.dy;
            capIn = Math.min(tBottom, tTop);
            capOut = Math.max(tBottom, tTop);
        } else if (!(ray.oy > y0 && ray.oy < y1)) {
            return Double.POSITIVE_INFINITY;
        }
        double in = Math.max(sideIn, capIn);
        double out = Math.min(sideOut, capOut);
        if (!(in < out)) {
            return Double.POSITIVE_INFINITY;
        }
        // on a tie at the rim the cap is taken: its normal's side of the ray is exact
        double t;
        int part;
        if (in > 0 && in < tMax) {
            t = in;
            part = capIn >= sideIn ? (ray.dy > 0 ? BOTTOM : TOP) : SIDE;
        } else if (out > 0 && out < tMax) {
            t = out;
            part = capOut <= sideOut ? (ray.dy > 0 ? TOP : BOTTOM) : SIDE;
        } else {
            return Double.POSITIVE_INFINITY;
        }
        if (partSink != null) {
            partSink.primitive = part;
        }
        return t;
    }

    private boolean withinHeight(double y) {
        return y >= y0 && y <= y1;
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        int previousPart = sr.primitive;
        double t = nearest(ray, sr.t, sr);
        if (t < sr.t) {
            sr.recordHit(t, this);
            return true;
        }
        sr.primitive = previousPart;
        return false;
    }

    /**
     * True when the ray crosses the surface in (0, tMax) at a point not shown to lie within
     * rounding of an end: a cylinder through the light's point touches the shadow ray's end and
     * does not block it. The crossings are those {@link #hit} finds: the side's roots within the
     * heights for the open cylinder; the entry and exit of the solid for the closed one.
     */
    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        double a = ray.dx * ray.dx + ray.dz * ray.dz;
        double sideIn = Double.NEGATIVE_INFINITY;
        double sideOut = Double.POSITIVE_INFINITY;
        if (a > 0) {
            double halfB = ray.ox * ray.dx + ray.oz * ray.dz;
            double s = halfB / a;
            double lx = ray.ox - s * ray.dx;
            double lz = ray.oz - s * ray.dz;
            double discriminant = radius * radius - (lx * lx + lz * lz);
            if (!(discriminant > 0)) {
                return false; // tangent to the side, or past it: touches or misses (see nearestOnSide)
            }
            double c = ray.ox * ray.ox + ray.oz * ray.oz - radius * radius;
            double q = -halfB - Math.copySign(Math.sqrt(a * discriminant), halfB);
            sideIn = Math.min(q / a, c / q);
            sideOut = Math.max(q / a, c / q);
        } else if (!closed || !(ray.ox * ray.ox + ray.oz * ray.oz < radius * radius)) {
            return false;
        }
        if (!closed) {
            return sideBlocks(ray, sideIn, tMax) || sideBlocks(ray, sideOut, tMax);
        }
        double capIn = Double.NEGATIVE_INFINITY;
        double capOut = Double.POSITIVE_INFINITY;
        if (ray.dy != 0) {
            double tBottom = (y0 - ray.oy) / ray.dy;
            double tTop = (y1 - ray.oy) / ray.dy;
            capIn = Math.min(tBottom, tTop);
            capOut = Math.max(tBottom, tTop);
        } else if (!(ray.oy > y0 && ray.oy < y1)) {
            return false;
        }
        double in = Math.max(sideIn, capIn);
        double out = Math.min(sideOut, capOut);
        if (!(in < out)) {
            return false;
        }
        if (in > 0 && out < tMax) {
            return true; // through the solid between the ends
        }
        boolean entry = capIn >= sideIn ? capBlocks(ray, in, tMax) : sideBlocks(ray, in, tMax);
        return entry || (capOut <= sideOut ? capBlocks(ray, out, tMax) : sideBlocks(ray, out, tMax));
    }

    /**
     * The side's crossing at t (of the open cylinder: within the heights) blocks unless it is
     * shown to touch an end: with x, z the point's coordinates, g = x^2 + z^2 - r^2 has slope
     * 2 (x dx + z dz), and the exact root lies within 2 |g| / |slope| of t while
     * 2 a delta &lt; |slope| (as for the sphere).
     */
    private boolean sideBlocks(Ray ray, double t, double tMax) {
        if (!(t > 0 && t < tMax) || !closed && !withinHeight(ray.atY(t))) {
            return false;
        }
        double x = ray.atX(t);
        double z = ray.atZ(t);
        double g2 = Rounding.gamma(2);
        double ex = g2 * (Math.abs(ray.ox) + Math.abs(t * ray.dx));
        double ez = g2 * (Math.abs(ray.oz) + Math.abs(t * ray.dz));
        double xd = x * ray.dx + z * ray.dz;
        double slope = 2 * (Math.abs(xd) - Rounding.gamma(2) * (Math.abs(x * ray.dx) + Math.abs(z * ray.dz))
                            - ex * Math.abs(ray.dx) - ez * Math.abs(ray.dz));
        if (!(slope > 0)) {
            return true;
        }
        double rr = radius * radius;
        double g = Math.abs(x * x + z * z - rr) + Rounding.gamma(3) * (x * x + z * z + rr)
                   + 2 * (Math.abs(x) * ex + Math.abs(z) * ez) + ex * ex + ez * ez
                   + 2 * (Math.abs(x) + Math.abs(z) + ex + ez) * (ray.originError + t * ray.directionError);
        double delta = 2 * g / slope;
        double a = ray.dx * ray.dx + ray.dz * ray.dz;
        return !(2 * a * delta < slope && (t <= delta || tMax - t <= delta));
    }

    /**
     * A cap's crossing at t = (y - oy) / dy blocks when it is certainly between the ray's ends: t
     * is off by gamma(2) of itself, and by (originError + t directionError) / |dy| from the ray's
     * own errors.
     */
    private static boolean capBlocks(Ray ray, double t, double tMax) {
        double margin = Rounding.gamma(2) * Math.abs(t) + (ray.originError + Math.abs(t) * ray.directionError) / Math.abs(ray.dy);
        return t - margin > 0 && tMax - t - margin > 0;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        double t = sr.t;
        double px = ray.atX(t);
        double py = ray.atY(t);
        double pz = ray.atZ(t);
        double g3 = Rounding.gamma(3);
        if (sr.primitive == SIDE) {
            // reproject radially: x and z then carry gamma(5)-sized errors (pbrt-v3, section 3.9.4)
            double scale = radius / Math.sqrt(px * px + pz * pz);
            px *= scale;
            pz *= scale;
            double g5 = Rounding.gamma(5);
            sr.hitError.set(g5 * Math.abs(px), g3 * (Math.abs(ray.oy) + Math.abs(t * ray.dy)), g5 * Math.abs(pz));
            sr.normal.set(px / radius, 0, pz / radius);
            if (sr.world.needsTextureCoordinates()) {
                sr.u = (Math.atan2(px, pz) + Math.PI) / (2 * Math.PI);
            } else {
                sr.scratch.skipped[Skipped.TEXTURE_COORDINATES]++;
                sr.u = 0;
            }
            sr.v = (py - y0) / (y1 - y0);
        } else {
            py = sr.primitive == TOP ? y1 : y0;
            sr.hitError.set(g3 * (Math.abs(ray.ox) + Math.abs(t * ray.dx)), 0,
                            g3 * (Math.abs(ray.oz) + Math.abs(t * ray.dz)));
            sr.normal.set(0, sr.primitive == TOP ? 1 : -1, 0);
            sr.u = 0.5 + 0.5 * px / radius;
            sr.v = 0.5 + 0.5 * pz / radius;
        }
        sr.hitPoint.set(px, py, pz);
        sr.geometricNormal.set(sr.normal);
    }

    @Override
    public BBox boundingBox() {
        return new BBox(-radius, y0, -radius, radius, y1, radius);
    }
}
