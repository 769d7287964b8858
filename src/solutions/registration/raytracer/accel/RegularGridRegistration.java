package raytracer.accel;

import raytracer.core.Registrar;
import raytracer.core.Registration;

/** Exercise 6's search structure: {@code --accel grid}, a grid over the bounded objects. */
public final class RegularGridRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.acceleration("grid", RegularGrid::new);
    }
}
