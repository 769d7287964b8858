package raytracer.filters;

import java.util.Set;
import raytracer.core.Registrar;
import raytracer.core.Registration;

/** Exercise 9's filter: {@code image: {filter: tent, filter-radius (pixels, 1)}} and {@code --filter tent}. */
public final class TentRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.filter("tent", Set.of("filter-radius"), p -> new Tent(p.number("filter-radius", 1)));
    }
}
