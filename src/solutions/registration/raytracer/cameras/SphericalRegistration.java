package raytracer.cameras;

import java.util.Set;
import raytracer.core.Registrar;
import raytracer.core.Registration;

/** Exercise 2's camera: {@code camera: {type: spherical, horizontal-fov (degrees, 360), vertical-fov (180)}}. */
public final class SphericalRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.camera("spherical", Set.of("horizontal-fov", "vertical-fov"), (eye, lookAt, up, p) ->
            new Spherical(eye, lookAt, up, p.number("horizontal-fov", 360), p.number("vertical-fov", 180)));
    }
}
