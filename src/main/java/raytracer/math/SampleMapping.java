package raytracer.math;

/**
 * Maps points of the unit square onto other domains (Suffern, chapter 6), as pure functions so
 * that cameras, lights and materials can share them.
 */
public final class SampleMapping {
    private SampleMapping() {
    }

    /**
     * Shirley and Chiu's concentric map of [0,1)^2 onto the unit disk: area-preserving and with
     * little distortion, so stratification survives. Writes (x, y, 0) into {@code out}.
     */
    public static void toUnitDisk(double sx, double sy, MutableVec3 out) {
        double a = 2 * sx - 1;
        double b = 2 * sy - 1;
        if (a == 0 && b == 0) {
            out.set(0, 0, 0);
            return;
        }
        double r;
        double phi;
        if (Math.abs(a) > Math.abs(b)) {
            r = a;
            phi = (Math.PI / 4) * (b / a);
        } else {
            r = b;
            phi = Math.PI / 2 - (Math.PI / 4) * (a / b);
        }
        out.set(r * Math.cos(phi), r * Math.sin(phi), 0);
    }

    /**
     * Maps [0,1)^2 onto the hemisphere around +z with density proportional to cos^e(theta)
     * (Suffern, eq. 7.11; the report's section 2.1 draws its glossy rays so): phi = 2 pi sx,
     * cos(theta) = (1 - sy)^(1/(e+1)).
     */
    public static void toHemisphere(double sx, double sy, double e, MutableVec3 out) {
        double cosTheta = Math.pow(1 - sy, 1 / (e + 1));
        double sinTheta = Math.sqrt(Math.max(0, 1 - cosTheta * cosTheta));
        double phi = 2 * Math.PI * sx;
        out.set(sinTheta * Math.cos(phi), sinTheta * Math.sin(phi), cosTheta);
    }

    /**
     * As {@link #toHemisphere}, around the unit {@code axis} instead of +z: theta is measured from
     * the axis (a glossy lobe around its mirror direction; with e = 1, cosine sampling around a
     * normal). The frame (a, b, axis) is built from whichever of y and x is further from the axis.
     */
    public static void toHemisphere(double sx, double sy, double e, double axisX, double axisY, double axisZ, MutableVec3 out) {
        double hx = Math.abs(axisX) > 0.9 ? 0 : 1;
        double hy = Math.abs(axisX) > 0.9 ? 1 : 0;
        // a = h x axis, normalised; b = axis x a
        double ax = hy * axisZ;
        double ay = -hx * axisZ;
        double az = hx * axisY - hy * axisX;
        double len = Math.sqrt(ax * ax + ay * ay + az * az);
        ax /= len;
        ay /= len;
        az /= len;
        double bx = axisY * az - axisZ * ay;
        double by = axisZ * ax - axisX * az;
        double bz = axisX * ay - axisY * ax;
        toHemisphere(sx, sy, e, out);
        double lx = out.x;
        double ly = out.y;
        double lz = out.z;
        out.set(lx * ax + ly * bx + lz * axisX, lx * ay + ly * by + lz * axisY, lx * az + ly * bz + lz * axisZ);
    }

    /** The solid-angle density of {@link #toHemisphere}: (e + 1) / (2 pi) cos^e(theta). */
    public static double hemispherePdf(double cosTheta, double e) {
        return cosTheta <= 0 ? 0 : (e + 1) / (2 * Math.PI) * Math.pow(cosTheta, e);
    }
}
