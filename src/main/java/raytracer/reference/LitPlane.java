package raytracer.reference;

import java.util.stream.IntStream;
import raytracer.image.Film;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/**
 * A diffuse plane under one unoccluded area light, seen by an orthographic camera: the image has an
 * exact value. A point p of the plane leaves radiance ka cd La (ambient) + kd cd / pi L Omega(p),
 * with Omega the light's projected solid angle ({@link ExactLight}); a pixel's value is that
 * radiance averaged over the pixel's area (the renderer spreads its samples over the pixel), times
 * the exposure, as the renderer's .pfm output stores it.
 *
 * <p>Pixel (x, y) covers film coordinates [x, x + 1) x [y, y + 1), y counted down from the top row;
 * film point (fx, fy) is seen along -w from eye + xs u + ys v, xs = (2 fx / width - 1) h aspect,
 * ys = (1 - 2 fy / height) h, h half the view height, with the frame of Suffern's section 9.2
 * (w from look-at to eye, u = up x w, v = w x u). Since the camera is orthographic, film and plane
 * are related by an affine map, so averaging over the film square averages over the plane's
 * parallelogram.
 */
public record LitPlane(int width, int height, Point3D eye, Point3D lookAt, Vector3D up, double viewHeight,
                       Point3D planePoint, Vector3D planeNormal, RGBColor diffuse, RGBColor ambient,
                       RGBColor lightRadiance, ExactLight light, double exposure) {

    /**
     * Checks that the scene is one this class can answer exactly.
     *
     * @param diffuse kd cd, the Lambertian albedo per channel
     * @param ambient ka cd La, the ambient radiance reflected per channel
     * @throws IllegalArgumentException with the reason when it is not
     */
    public LitPlane {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be at least 1x1, got " + width + "x" + height);
        }
        if (!(viewHeight > 0)) {
            throw new IllegalArgumentException("the view height must be positive, got " + viewHeight);
        }
        Vector3D w = eye.sub(lookAt);
        if (!(w.length() > 0) || !(up.cross(w).length() > 1e-9 * up.length() * w.length())) {
            throw new IllegalArgumentException("the camera needs an eye apart from its look-at point and an up vector"
                                               + " that is not parallel to the view");
        }
        if (!(planeNormal.length() > 0)) {
            throw new IllegalArgumentException("the plane needs a non-zero normal");
        }
        planeNormal = planeNormal.normalize();
        Vector3D n = planeNormal;
        if (!(w.normalize().dot(n) > 1e-9)) {
            throw new IllegalArgumentException("the camera must look at the side of the plane its normal points to");
        }
        if (!light.above(planePoint.x(), planePoint.y(), planePoint.z(), n.x(), n.y(), n.z())) {
            throw new IllegalArgumentException("the light must lie wholly above the plane, on the side its normal points to");
        }
        // the camera rays start on the view window: all of it must be above the plane to see it
        View view = View.of(eye, lookAt, up, viewHeight, width, height);
        for (int corner = 0; corner < 4; corner++) {
            Point3D o = view.origin(corner % 2 * width, corner / 2 * height);
            if (!(o.sub(planePoint).dot(n) > 0)) {
                throw new IllegalArgumentException("the camera's view window must lie above the plane, on the side its normal points to");
            }
        }
    }

    /** The same scene at another resolution. */
    public LitPlane withResolution(int w, int h) {
        return new LitPlane(w, h, eye, lookAt, up, viewHeight, planePoint, planeNormal, diffuse, ambient, lightRadiance,
                            light, exposure);
    }

    /** The exact image, each pixel averaged by the {@code order} x {@code order} Gauss-Legendre rule. */
    public Film render(int order) {
        GaussLegendre rule = new GaussLegendre(order);
        View view = View.of(eye, lookAt, up, viewHeight, width, height);
        Film film = new Film(width, height);
        IntStream.range(0, height).parallel().forEach(y -> {
            for (int x = 0; x < width; x++) {
                double omega = pixelProjectedSolidAngle(x, y, rule, view);
                double r = ambient.r() + diffuse.r() / Math.PI * lightRadiance.r() * omega;
                double g = ambient.g() + diffuse.g() / Math.PI * lightRadiance.g() * omega;
                double b = ambient.b() + diffuse.b() / Math.PI * lightRadiance.b() * omega;
                film.set(x, y, r * exposure, g * exposure, b * exposure);
            }
        });
        return film;
    }

    /** The light's projected solid angle averaged over pixel (x, y). */
    double pixelProjectedSolidAngle(int x, int y, GaussLegendre rule, View view) {
        double sum = 0;
        for (int i = 0; i < rule.order(); i++) {
            for (int j = 0; j < rule.order(); j++) {
                sum += rule.weight(i) * rule.weight(j) * projectedSolidAngleAt(x + rule.node(i), y + rule.node(j), view);
            }
        }
        return sum;
    }

    /**
     * The camera frame (Suffern, section 9.2: w from look-at to eye, u = up x w, v = w x u) and the
     * film's size; it maps film points to the origins of the camera's rays.
     */
    record View(Point3D eye, Vector3D u, Vector3D v, Vector3D w, double halfWidth, double halfHeight, int width, int height) {

        static View of(Point3D eye, Point3D lookAt, Vector3D up, double viewHeight, int width, int height) {
            Vector3D w = eye.sub(lookAt).normalize();
            Vector3D u = up.cross(w).normalize();
            return new View(eye, u, w.cross(u), w, viewHeight / 2 * width / height, viewHeight / 2, width, height);
        }

        /** The origin of the camera ray through film point (fx, fy): the ray runs along -w from it. */
        Point3D origin(double fx, double fy) {
            double xs = (2 * fx / width - 1) * halfWidth;
            double ys = (1 - 2 * fy / height) * halfHeight;
            return eye.add(u.scale(xs)).add(v.scale(ys));
        }
    }

    /** The projected solid angle of the light at the plane point seen at film point (fx, fy). */
    double projectedSolidAngleAt(double fx, double fy, View view) {
        Point3D origin = view.origin(fx, fy);
        Vector3D w = view.w();
        Vector3D n = planeNormal;
        // the ray origin - t w meets the plane where (origin - t w - planePoint) . n = 0
        double t = origin.sub(planePoint).dot(n) / w.dot(n);
        return light.projectedSolidAngle(origin.x() - t * w.x(), origin.y() - t * w.y(), origin.z() - t * w.z(),
                                         n.x(), n.y(), n.z());
    }
}
