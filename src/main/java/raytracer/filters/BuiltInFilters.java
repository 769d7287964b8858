package raytracer.filters;

import java.util.Set;
import raytracer.core.PixelFilter;
import raytracer.core.Registrar;
import raytracer.core.Registration;

/** The book's box filter and the Gaussian (pbrt-v3, section 7.8), whose width is the image's {@code filter-stddev}. */
public final class BuiltInFilters implements Registration {
    @Override
    public void register(Registrar registrar) {
        registrar.filter("box", Set.of(), p -> PixelFilter.BOX);
        registrar.filter("gaussian", Set.of("filter-stddev"), p -> {
            double stddev = p.number("filter-stddev", Gaussian.DEFAULT_STDDEV);
            if (!Gaussian.allows(stddev)) {
                throw p.error("filter-stddev", "'filter-stddev' in image must be " + Gaussian.MIN_STDDEV + " to "
                                               + Gaussian.MAX_STDDEV + " pixels, got " + stddev);
            }
            return new Gaussian(stddev);
        });
    }
}
