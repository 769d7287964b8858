package raytracer.cli;

import picocli.CommandLine.Option;

/**
 * The options of render and the Spark job that converge has not, since each writes one image of
 * the scene: its samples per pixel (converge measures a list of counts), its PNG's encoding and
 * the first hit's terms (converge measures the full image's radiance). A mixin beside
 * {@link RenderOptions}, which checks them with the rest.
 */
public final class ImageOptions {
    @Option(names = {"-s", "--spp"}, paramLabel = "N", description = "Samples per pixel (overrides the scene).")
    Integer samples;

    @Option(names = "--encoding", paramLabel = "E",
            description = "PNG encoding (overrides the scene): srgb, or linear (clamped radiance as the code value, as the report did).")
    String encoding;

    @Option(names = "--pass", paramLabel = "PASS",
            description = "Terms of the first hit (report figures 4 and 6): full, direct, reflection, refraction, "
                          + "magenta-reflection or no-fresnel. Default: the scene's, else full.")
    String pass;
}
