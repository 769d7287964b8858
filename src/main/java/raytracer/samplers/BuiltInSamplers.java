package raytracer.samplers;

import raytracer.core.Registrar;
import raytracer.core.Registration;

/** The book's sample patterns (Suffern, chapter 5) and two beyond it, by the names scenes and options use, in this order. */
public final class BuiltInSamplers implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.sampler("regular", Regular::new);
        registrar.sampler("random", PureRandom::new);
        registrar.sampler("jittered", Jittered::new);
        registrar.sampler("n-rooks", NRooks::new);
        registrar.sampler("multi-jittered", MultiJittered::new);
        registrar.sampler("correlated-multi-jittered", CorrelatedMultiJittered::new);
        registrar.sampler("hammersley", Hammersley::new);
        registrar.sampler("sobol", Sobol::new);
    }
}
