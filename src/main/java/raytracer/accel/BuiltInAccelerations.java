package raytracer.accel;

import raytracer.core.Registrar;
import raytracer.core.Registration;

/**
 * The search structures of {@code --accel}: {@code auto} (a median-split BVH from
 * {@link Aggregation#AUTO_THRESHOLD} bounded objects on), {@code list}, and a BVH split at the
 * median or by the surface area heuristic whenever there are two objects to split.
 */
public final class BuiltInAccelerations implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.acceleration("auto", bounded -> bounded.size() >= Aggregation.AUTO_THRESHOLD ? ObjectBVH.build(bounded, false) : null);
        registrar.acceleration("list", bounded -> null);
        registrar.acceleration("median", bounded -> bounded.size() > 1 ? ObjectBVH.build(bounded, false) : null);
        registrar.acceleration("sah", bounded -> bounded.size() > 1 ? ObjectBVH.build(bounded, true) : null);
    }
}
