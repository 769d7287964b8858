package raytracer.core;

import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/** {@link Parameters#NONE}: an entry without keys, whose every value is the type's default. */
final class NoParameters implements Parameters {

    @Override
    public boolean has(String key) {
        return false;
    }

    @Override
    public String string(String key, String fallback) {
        return fallback;
    }

    @Override
    public double number(String key, double fallback) {
        return fallback;
    }

    @Override
    public double number(String key, double fallback, double min, boolean strict) {
        return fallback;
    }

    @Override
    public int integer(String key, int fallback, int min, int max) {
        return fallback;
    }

    @Override
    public boolean bool(String key, boolean fallback) {
        return fallback;
    }

    @Override
    public Point3D point(String key, Point3D fallback) {
        return fallback;
    }

    @Override
    public Point3D requiredPoint(String key) throws ParameterException {
        throw error(key, "needs the key '" + key + "'");
    }

    @Override
    public Vector3D vector(String key, Vector3D fallback) {
        return fallback;
    }

    @Override
    public Vector3D requiredVector(String key) throws ParameterException {
        throw error(key, "needs the key '" + key + "'");
    }

    @Override
    public RGBColor color(String key, RGBColor fallback) {
        return fallback;
    }

    @Override
    public void checkEmission(String scaleKey, double scale, String colorKey, RGBColor color) {
        // the defaults a type gives itself are its own to keep within range
    }

    @Override
    public ParameterException error(String key, String message) {
        return new ParameterException(message);
    }
}
