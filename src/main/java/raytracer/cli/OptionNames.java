package raytracer.cli;

import java.util.Arrays;
import java.util.Iterator;
import java.util.Locale;
import raytracer.accel.Aggregation;
import raytracer.filters.Filters;
import raytracer.samplers.Samplers;

/**
 * The names an option takes, read from the registries when help is printed (picocli's
 * {@code ${COMPLETION-CANDIDATES}}), so that a sampler, filter or search structure registered
 * there, as the exercises of docs/teaching.md do, is listed without editing the option's text.
 */
final class OptionNames {
    private OptionNames() {
    }

    /** The sample patterns of {@link Samplers}. */
    static final class SamplerNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return Samplers.names().iterator();
        }
    }

    /** The pixel filters of {@link Filters}. */
    static final class FilterNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return Filters.names().iterator();
        }
    }

    /** The search structures of {@link Aggregation.Mode}, as {@code --accel} spells them. */
    static final class AccelerationNames implements Iterable<String> {
        @Override
        public Iterator<String> iterator() {
            return Arrays.stream(Aggregation.Mode.values()).map(m -> m.name().toLowerCase(Locale.ROOT)).iterator();
        }
    }
}
