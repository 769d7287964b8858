package raytracer.cli;

import picocli.CommandLine.Option;
import raytracer.api.FilterChoice;

/** The pixel-filter options, two of {@link RenderOptions}' (a picocli mixin within it). */
final class FilterOptions {
    @Option(names = "--filter", paramLabel = "NAME", completionCandidates = OptionNames.FilterNames.class,
            description = "How pixels are made from samples (overrides the scene): ${COMPLETION-CANDIDATES}. box is the book's "
                          + "(the average of the pixel's own samples), gaussian has a standard deviation of 0.5 pixel and a radius "
                          + "of 2 (less noise, slightly softer).")
    String filter;

    @Option(names = "--filter-stddev", paramLabel = "S",
            description = "The Gaussian filter's standard deviation in pixels, 0.2 to 2 (implies --filter gaussian; its radius is 4 S).")
    Double filterStddev;

    /** The two options checked together; IllegalArgumentException says what is wrong. */
    FilterChoice choice() {
        return FilterChoice.parse(filter, filterStddev);
    }
}
