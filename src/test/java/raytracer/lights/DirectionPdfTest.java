package raytracer.lights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/**
 * A light's {@code directionPdf} is the density, per unit solid angle seen from a point, with which
 * its own sampling chooses a direction: over the directions that reach the light it integrates to
 * the share of samples that can reach the point. Checked by integrating it over directions, with
 * the hit on the light found here by plain geometry, from points that see the light at grazing
 * angles (a cosine at the light well below 1, where dropping that cosine from d^2 / (A cos) would
 * show: it feeds the MIS weight of glossy rays that hit a visible light).
 */
class DirectionPdfTest {
    /** Grid cells per side of the gnomonic plane one unit from the point, across the light's directions. */
    private static final int CELLS = 1500;

    /** Where a ray from the point in direction (dx, dy, dz) meets the light: distance t (unit direction), cosine at the light; null if it misses. */
    private interface Geometry {
        double[] hit(double dx, double dy, double dz);
    }

    /**
     * The integral of the light's density over the directions from {@code p} that meet it, by the
     * midpoint rule on the plane through {@code p + w} perpendicular to {@code w} (the direction
     * to the light's centre): dω = cos^3(α) dx dy there, α the angle from {@code w}.
     */
    private static double integrate(AreaLight light, Point3D p, Vector3D towards, double halfWidth, Geometry g) {
        Vector3D w = towards.normalize();
        Vector3D helper = Math.abs(w.x()) < 0.9 ? new Vector3D(1, 0, 0) : new Vector3D(0, 1, 0);
        Vector3D e1 = helper.cross(w).normalize();
        Vector3D e2 = w.cross(e1);
        double h = 2 * halfWidth / CELLS;
        double sum = 0;
        int hits = 0;
        for (int i = 0; i < CELLS; i++) {
            double x = -halfWidth + (i + 0.5) * h;
            for (int j = 0; j < CELLS; j++) {
                double y = -halfWidth + (j + 0.5) * h;
                double dx = w.x() + x * e1.x() + y * e2.x();
                double dy = w.y() + x * e1.y() + y * e2.y();
                double dz = w.z() + x * e1.z() + y * e2.z();
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double[] hit = g.hit(dx / len, dy / len, dz / len);
                boolean border = i == 0 || j == 0 || i == CELLS - 1 || j == CELLS - 1;
                assertTrue(hit == null || !border, "the grid must hold the whole light");
                if (hit != null) {
                    double cosAlpha = 1 / len;
                    sum += light.directionPdf(p.x(), p.y(), p.z(), hit[0], hit[1]) * cosAlpha * cosAlpha * cosAlpha * h * h;
                    hits++;
                }
            }
        }
        assertTrue(hits > 100_000, "the light is resolved: " + hits + " cells hit");
        return sum;
    }

    @Test
    void aRectangleSeenAtAGrazingAngleIntegratesToOne() {
        // the light spans x, z in [-1, 1] at y = 2, facing down; the point sees its centre 18 degrees above its plane
        AreaLight light = AreaLight.rectangle(new Point3D(-1, 2, -1), new Vector3D(0, 0, 2), new Vector3D(2, 0, 0), 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(6, 0, 0);
        double cosAtCentre = 2 / Math.sqrt(36 + 4);
        assertTrue(cosAtCentre < 0.35);
        double integral = integrate(light, p, new Vector3D(-6, 2, 0), 0.2, (dx, dy, dz) -> {
            double t = (2 - p.y()) / dy;
            double x = p.x() + t * dx;
            double z = p.z() + t * dz;
            return t > 0 && Math.abs(x) <= 1 && Math.abs(z) <= 1 ? new double[] {t, Math.abs(dy)} : null;
        });
        assertEquals(1, integral, 2e-3);
    }

    @Test
    void aDiskSeenAtAGrazingAngleIntegratesToOne() {
        AreaLight light = AreaLight.disk(new Point3D(0, 2, 0), new Vector3D(0, -1, 0), 1, 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(5, 0, 1);
        double integral = integrate(light, p, new Vector3D(-5, 2, -1), 0.25, (dx, dy, dz) -> {
            double t = (2 - p.y()) / dy;
            double x = p.x() + t * dx;
            double z = p.z() + t * dz;
            return t > 0 && x * x + z * z <= 1 ? new double[] {t, Math.abs(dy)} : null;
        });
        assertEquals(1, integral, 2e-3);
    }

    /**
     * A sphere sampled uniformly over its whole area: only the cap facing the point can be reached,
     * a share (1 - r / D) / 2 of its area, D the distance to its centre. Near it the cosines at the
     * light run from 1 at the centre of the cap to 0 at its rim.
     */
    @Test
    void aSphereIntegratesToTheShareOfItsAreaThePointSees() {
        double r = 1;
        double distance = 1.6;
        AreaLight light = AreaLight.sphere(new Point3D(0, 0, 0), r, 1, RGBColor.WHITE, 1);
        Point3D p = new Point3D(distance, 0, 0);
        double integral = integrate(light, p, new Vector3D(-1, 0, 0), 1.3, (dx, dy, dz) -> {
            // |p + t d|^2 = r^2, the nearer root
            double b = p.x() * dx + p.y() * dy + p.z() * dz;
            double c = distance * distance - r * r;
            double disc = b * b - c;
            if (disc < 0) {
                return null;
            }
            double t = -b - Math.sqrt(disc);
            Normal n = new Normal(p.x() + t * dx, p.y() + t * dy, p.z() + t * dz);
            double cos = -(n.x() * dx + n.y() * dy + n.z() * dz) / r;
            return new double[] {t, cos};
        });
        assertEquals((1 - r / distance) / 2, integral, 3e-3);
    }
}
