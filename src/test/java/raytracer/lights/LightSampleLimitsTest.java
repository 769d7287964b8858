package raytracer.lights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.MutableVec3;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.samplers.MultiJittered;

/**
 * Light samples where the solid-angle formulas reach their limits: a point in a rectangle's plane,
 * one seen edge-on, one so far that the rectangle falls back to area sampling, a point inside a
 * sphere, on it, just off it and very far from it; at scales from 1e-4 to 1e6 and moved far from
 * the origin. Every sample's weight G / pdf must be finite and not negative, its direction a unit
 * vector where the weight is positive; where the light samples by area, pdf is 1 / area.
 */
class LightSampleLimitsTest {

    private static ShadeRec shadeRec() {
        World world = new World(new ViewPlane(1, 1, 1, new MultiJittered(), 0, 1),
            new Orthographic(new Point3D(0, 5, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1), new Ambient(0, RGBColor.WHITE));
        return new WorkerScratch(world).shadeRec(0);
    }

    /** Samples the light from p on a 7 x 7 grid and checks each sample; returns the mean of G / pdf (the solid angle reached). */
    private static double check(String what, AreaLight light, double px, double py, double pz) {
        ShadeRec sr = shadeRec();
        sr.hitPoint.set(px, py, pz);
        MutableVec3 wi = new MutableVec3();
        double sum = 0;
        for (int i = 0; i < 7; i++) {
            for (int j = 0; j < 7; j++) {
                double d = light.sample(sr, (i + 0.5) / 7, (j + 0.5) / 7, wi);
                double pdf = light.pdf(sr);
                double weight = light.G(sr) / pdf;
                assertTrue(pdf > 0 && pdf < Double.POSITIVE_INFINITY, what + ": pdf " + pdf);
                assertTrue(weight >= 0 && weight < Double.POSITIVE_INFINITY, what + ": G / pdf " + weight);
                if (weight > 0) { // else the shading drops the sample: from a point on the light itself, the direction is 0 / 0
                    assertTrue(d > 0 && d < Double.POSITIVE_INFINITY, what + ": distance " + d);
                    assertEquals(1, wi.length(), 1e-12, what + ": a unit direction");
                }
                sum += weight;
            }
        }
        return sum / 49;
    }

    @Test
    void rectangleSamplesStayFiniteAtTheLimits() {
        SplittableRandom random = new SplittableRandom(5);
        for (int i = 0; i < 400; i++) {
            double s = Math.exp(random.nextDouble(Math.log(1e-4), Math.log(1e6)));
            double shift = random.nextBoolean() ? 0 : s * 1e4;
            Point3D corner = new Point3D(shift - s, 2 * s, -s);
            AreaLight light = AreaLight.rectangle(corner, new Vector3D(2 * s, 0, 0), new Vector3D(0, 0, 2 * s), 1, RGBColor.WHITE, 1);
            // in the plane, inside and outside the rectangle; a hair in front of it, below its
            // middle and far off to the side (edge-on); behind it; and so far off that it falls back to area sampling
            double[][] points = {{shift, 2 * s, 0}, {shift + 5 * s, 2 * s, 0}, {shift, 2 * s * (1 - 1e-13), 0},
                                 {shift + 40 * s, 2 * s * (1 - 1e-9), 0}, {shift, 3 * s, 0}, {shift + 3e3 * s, -1e3 * s, 0}};
            for (double[] p : points) {
                check("rectangle of size " + s + " from " + java.util.Arrays.toString(p), light, p[0], p[1], p[2]);
            }
        }
    }

    /**
     * A rectangle is sampled by solid angle, G / pdf being that solid angle, unless the solid angle
     * is below what the map resolves; then, edge-on or small and far, by area, pdf being 1 / area.
     * A 1 x 1 light seen edge-on from 1e-4 and 1e-7 below its plane, 1 to 2 away (about 4e-5 and
     * 4e-8 sr), and from 600 away (2.8e-6 sr).
     */
    @Test
    void tinySolidAnglesAreSampledByArea() {
        AreaLight light = AreaLight.rectangle(new Point3D(1, 0, -0.5), new Vector3D(1, 0, 0), new Vector3D(0, 0, 1), 1, RGBColor.WHITE, 1);
        // seen from (0, -h, 0), the solid angle is h times the integral of 1 / (x^2 + z^2)^(3/2) over it, to first order in h
        double perHeight = 0;
        int n = 2000;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double x = 1 + (i + 0.5) / n;
                double z = -0.5 + (j + 0.5) / n;
                perHeight += Math.pow(x * x + z * z, -1.5) / ((double) n * n);
            }
        }
        double grazing = 1e-4 * perHeight;
        assertTrue(grazing > SphericalRectangle.MIN_SOLID_ANGLE && 1e-2 * grazing < SphericalRectangle.MIN_SOLID_ANGLE);
        assertEquals(grazing, check("edge-on, 1e-4 below", light, 0, -1e-4, 0), 1e-6 * grazing);
        ShadeRec sr = shadeRec();
        sr.hitPoint.set(0, -1e-7, 0);
        light.sample(sr, 0.3, 0.6, new MutableVec3());
        assertEquals(1, light.pdf(sr), "edge-on, 1e-7 below: 1 / area");
        assertEquals(1.3, sr.lightPoint.x, 1e-12, "the corner plus u a plus v b");
        AreaLight far = AreaLight.rectangle(new Point3D(-0.5, 600, -0.5), new Vector3D(1, 0, 0), new Vector3D(0, 0, 1), 1, RGBColor.WHITE, 1);
        sr.hitPoint.set(0, 0, 0);
        far.sample(sr, 0.3, 0.6, new MutableVec3());
        assertEquals(1, far.pdf(sr), "600 away: 1 / area");
    }

    @Test
    void sphereSamplesStayFiniteAtTheLimits() {
        SplittableRandom random = new SplittableRandom(6);
        for (int i = 0; i < 400; i++) {
            double r = Math.exp(random.nextDouble(Math.log(1e-4), Math.log(1e6)));
            double shift = random.nextBoolean() ? 0 : r * 1e4;
            AreaLight light = AreaLight.sphere(new Point3D(shift, 0, 0), r, 1, RGBColor.WHITE, 1);
            // the centre, inside, on the surface, a hair outside, and 1e6 radii away
            double[] offsets = {0, 0.5 * r, r, r * (1 + 1e-12), 1e6 * r};
            for (double o : offsets) {
                double reached = check("sphere of radius " + r + " from " + o, light, shift + o, 0, 0);
                if (o < r) {
                    assertEquals(0, reached, "inside, the sphere's surface faces away");
                }
            }
        }
    }

    /**
     * Outside a sphere every sample lies on the cap the point sees, and the map is the cone's:
     * the sampled direction makes sin^2(theta) = x (2 - x) with the axis, x = u (1 - cos theta_max),
     * cos theta_max = sqrt(1 - (r / D)^2), computed here from the cross product of the directions.
     */
    @Test
    void sphereSamplesFillTheConeUniformly() {
        SplittableRandom random = new SplittableRandom(7);
        MutableVec3 point = new MutableVec3();
        MutableVec3 normal = new MutableVec3();
        MutableVec3 p = new MutableVec3();
        for (int i = 0; i < 2000; i++) {
            double r = Math.exp(random.nextDouble(Math.log(1e-4), Math.log(1e6)));
            double d = r * (1 + Math.exp(random.nextDouble(Math.log(1e-9), Math.log(1e6))));
            SphereEmitter sphere = new SphereEmitter(new Point3D(0, 0, 0), r);
            Vector3D axis = new Vector3D(random.nextDouble(-1, 1), random.nextDouble(-1, 1), random.nextDouble(-1, 1)).normalize();
            p.set(-d * axis.x(), -d * axis.y(), -d * axis.z());
            double sin2Max = (r / d) * (r / d);
            double om = sin2Max / (1 + Math.sqrt((d - r) * (d + r)) / d);
            double u = random.nextDouble();
            double pdf = sphere.sample(p, u, random.nextDouble(), point, normal);
            double toX = point.x - p.x;
            double toY = point.y - p.y;
            double toZ = point.z - p.z;
            double length = Math.sqrt(toX * toX + toY * toY + toZ * toZ);
            assertEquals(r, Math.sqrt(point.x * point.x + point.y * point.y + point.z * point.z), 1e-12 * r, "on the sphere");
            assertEquals(1, normal.length(), 1e-12);
            assertTrue(-normal.dot(toX, toY, toZ) / length > -1e-9, "on the cap the point sees");
            double cx = (toY * axis.z() - toZ * axis.y()) / length;
            double cy = (toZ * axis.x() - toX * axis.z()) / length;
            double cz = (toX * axis.y() - toY * axis.x()) / length;
            double x = u * om;
            assertEquals(x * (2 - x), cx * cx + cy * cy + cz * cz, 1e-6 * x * (2 - x) + 1e-14, "sin^2 theta, D / r = " + d / r);
            double g = Emitter.geometricFactor(p, point, normal);
            if (g > 0) {
                assertEquals(g / (2 * Math.PI * om), pdf, 1e-9 * pdf, "the cone's density over area");
            }
        }
    }
}
