package raytracer.lights;

import raytracer.math.Vec3;

/** The surface of an area light, sampled uniformly by area. */
interface Emitter {

    /** Writes the point for (u, v) in [0,1)^2 and the unit normal on its emitting side. */
    void sample(double u, double v, Vec3 point, Vec3 normal);

    double area();
}
