package raytracer.core;

import raytracer.math.Point3D;
import raytracer.math.Vector3D;

/**
 * How a registered camera is made: every camera is placed by an eye, a point it looks at and an up
 * direction (Suffern's {@code Camera}, chapter 9), which the reader reads for it with their
 * defaults; the rest are its own values.
 */
@FunctionalInterface
public interface CameraFactory {
    Camera make(Point3D eye, Point3D lookAt, Vector3D up, Parameters p) throws ParameterException;
}
