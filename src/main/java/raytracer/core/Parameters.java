package raytracer.core;

import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;

/**
 * The values of one entry of a scene file (a light, an object, a material, ...) by key, as a
 * registered type reads them to make itself ({@link Registrar}): Mitsuba 3's {@code Properties},
 * pbrt-v4's {@code ParameterDictionary}. Keys the type did not declare are refused before it is
 * asked; every getter checks its value, and a {@link ParameterException} names the file, line and
 * column, the key and what was expected. A getter given a key that is absent returns its fallback.
 */
public interface Parameters {
    /** No values: every getter returns its fallback (a type made by name alone, as {@code --filter tent}). */
    Parameters NONE = new NoParameters();

    boolean has(String key);

    /** A single value as text. */
    String string(String key, String fallback) throws ParameterException;

    double number(String key, double fallback) throws ParameterException;

    /** A number that must be at least {@code min}, or above it when {@code strict}. */
    double number(String key, double fallback, double min, boolean strict) throws ParameterException;

    /** A whole number from {@code min} to {@code max}. */
    int integer(String key, int fallback, int min, int max) throws ParameterException;

    boolean bool(String key, boolean fallback) throws ParameterException;

    Point3D point(String key, Point3D fallback) throws ParameterException;

    /** A point that the entry must give. */
    Point3D requiredPoint(String key) throws ParameterException;

    Vector3D vector(String key, Vector3D fallback) throws ParameterException;

    /** A vector that the entry must give. */
    Vector3D requiredVector(String key) throws ParameterException;

    /** A linear RGB colour with no negative component. */
    RGBColor color(String key, RGBColor fallback) throws ParameterException;

    /**
     * Checks what a light emits, {@code scale} (the value of {@code scaleKey}) times the brightest
     * channel of {@code color} (of {@code colorKey}): above the largest float an image could only
     * hold infinity.
     */
    void checkEmission(String scaleKey, double scale, String colorKey, RGBColor color) throws ParameterException;

    /** An error about the value of {@code key} (about the whole entry when it is absent), placed in the file. */
    ParameterException error(String key, String message);
}
