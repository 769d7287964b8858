package raytracer.cameras;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.core.ViewPlane;
import raytracer.math.Point3D;
import raytracer.math.Ray;
import raytracer.math.Vector3D;

/** The thin lens against the pinhole it generalises (Suffern, section 10.2). */
class ThinLensTest {
    private static final Point3D EYE = new Point3D(1, 2, 9);
    private static final Point3D LOOK_AT = new Point3D(-1, 0.5, 0);
    private static final double FOCAL = 7.5;
    private static final double LENS = 0.4;
    private static final ViewPlane VP = new ViewPlane(320, 200, 1, (n, rng, xs, ys) -> { }, 2, 1);

    @Test
    void everyLensSampleOfAPixelMeetsThePinholeRayOnTheFocalPlane() {
        Pinhole pinhole = new Pinhole(EYE, LOOK_AT, Vector3D.UP, 40);
        ThinLens lens = new ThinLens(EYE, LOOK_AT, Vector3D.UP, 40, LENS, FOCAL);
        Vector3D forward = new Vector3D(LOOK_AT.x() - EYE.x(), LOOK_AT.y() - EYE.y(), LOOK_AT.z() - EYE.z()).normalize();
        SplittableRandom r = new SplittableRandom(1);
        Ray p = new Ray();
        Ray t = new Ray();
        double spread = 0;
        for (int i = 0; i < 10_000; i++) {
            double px = r.nextDouble(0, VP.hres());
            double py = r.nextDouble(0, VP.vres());
            double a = r.nextDouble(0, 2 * Math.PI);
            double rho = Math.sqrt(r.nextDouble());
            double lx = rho * Math.cos(a);
            double ly = rho * Math.sin(a);
            pinhole.generateRay(VP, px, py, 0, 0, p);
            lens.generateRay(VP, px, py, lx, ly, t);
            assertEquals(1, t.dx * t.dx + t.dy * t.dy + t.dz * t.dz, 1e-12, "unit direction");
            // the lens sample's origin lies in the lens plane, within the aperture
            double ox = t.ox - EYE.x();
            double oy = t.oy - EYE.y();
            double oz = t.oz - EYE.z();
            assertEquals(0, ox * forward.x() + oy * forward.y() + oz * forward.z(), 1e-12);
            assertTrue(Math.sqrt(ox * ox + oy * oy + oz * oz) <= LENS * (1 + 1e-12));
            spread = Math.max(spread, Math.sqrt(ox * ox + oy * oy + oz * oz));
            // both rays reach the plane at distance FOCAL in front of the eye at the same point
            double sp = FOCAL / (p.dx * forward.x() + p.dy * forward.y() + p.dz * forward.z());
            double st = FOCAL / (t.dx * forward.x() + t.dy * forward.y() + t.dz * forward.z());
            assertEquals(p.ox + sp * p.dx, t.ox + st * t.dx, 1e-9, "x, sample " + i);
            assertEquals(p.oy + sp * p.dy, t.oy + st * t.dy, 1e-9, "y, sample " + i);
            assertEquals(p.oz + sp * p.dz, t.oz + st * t.dz, 1e-9, "z, sample " + i);
        }
        assertTrue(spread > 0.9 * LENS, "the samples use the whole aperture: " + spread);
    }

    @Test
    void aClosedApertureIsThePinhole() {
        Pinhole pinhole = new Pinhole(EYE, LOOK_AT, Vector3D.UP, 40);
        ThinLens lens = new ThinLens(EYE, LOOK_AT, Vector3D.UP, 40, 0, FOCAL);
        Ray p = new Ray();
        Ray t = new Ray();
        for (double px : new double[] {0, 17.25, 160, 319.9}) {
            for (double py : new double[] {0, 100, 199.5}) {
                pinhole.generateRay(VP, px, py, 0, 0, p);
                lens.generateRay(VP, px, py, 0.7, -0.3, t);
                double[] a = {p.ox, p.oy, p.oz, p.dx, p.dy, p.dz};
                double[] b = {t.ox, t.oy, t.oz, t.dx, t.dy, t.dz};
                for (int k = 0; k < 6; k++) {
                    assertEquals(a[k], b[k], 1e-12, "pixel " + px + ", " + py + ", component " + k);
                }
            }
        }
        assertEquals(false, lens.needsLensSamples(), "no lens samples are drawn for a closed aperture");
    }

    @Test
    void badSettingsAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> new ThinLens(EYE, LOOK_AT, Vector3D.UP, 40, -1, FOCAL));
        assertThrows(IllegalArgumentException.class, () -> new ThinLens(EYE, LOOK_AT, Vector3D.UP, 40, 0.1, 0));
        assertThrows(IllegalArgumentException.class, () -> new ThinLens(EYE, LOOK_AT, Vector3D.UP, 40, Double.NaN, 1));
    }
}
