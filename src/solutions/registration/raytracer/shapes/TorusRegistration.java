package raytracer.shapes;

import java.util.Set;
import raytracer.core.Registrar;
import raytracer.core.Registration;

/** Exercise 5's object: {@code {type: torus, swept-radius (a, 1), tube-radius (b, 0.25)}} in a scene's objects. */
public final class TorusRegistration implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.object("torus", Set.of("swept-radius", "tube-radius"),
                         p -> new Torus(p.number("swept-radius", 1, 0, true), p.number("tube-radius", 0.25, 0, true)));
    }
}
