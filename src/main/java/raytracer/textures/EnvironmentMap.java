package raytracer.textures;

import raytracer.core.Background;
import raytracer.image.Film;
import raytracer.math.Ray;
import raytracer.math.MutableRgb;

/**
 * An equirectangular (latitude-longitude) environment: the direction d looks up
 * u = 1/2 + atan2(d_x, -d_z) / (2 pi), v = acos(d_y) / pi, so the image's centre is seen looking
 * down -z, its top row straight up, and +x a quarter turn to the right. Radiance is scaled by
 * {@code intensity}. A turn of the map by an angle about +y (right-handed, so 90 degrees brings what
 * was seen down -z to -x) adds angle / 360 to u.
 */
public final class EnvironmentMap implements Background {
    private final Film image;
    private final double intensity;
    private final double uOffset;

    public EnvironmentMap(Film image, double intensity) {
        this(image, intensity, 0);
    }

    /** A map turned by {@code rotateYDegrees} about the vertical axis. */
    public EnvironmentMap(Film image, double intensity, double rotateYDegrees) {
        this.image = image;
        this.intensity = intensity;
        this.uOffset = rotateYDegrees / 360;
    }

    @Override
    public void radiance(Ray ray, MutableRgb out) {
        double len = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        double dy = Math.max(-1, Math.min(1, ray.dy / len));
        double u = 0.5 + uOffset + Math.atan2(ray.dx, -ray.dz) / (2 * Math.PI);
        double v = Math.acos(dy) / Math.PI;
        Bilinear.lookup(image, u, v, false, out);
        out.scale(intensity);
    }
}
