package raytracer.samplers;

import raytracer.core.Registrar;
import raytracer.core.Registration;

/** Exercise 1's sampler by name: {@code image: {sampler: halton}} and {@code --sampler halton}. */
public final class HaltonRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.sampler("halton", Halton::new);
    }
}
