package raytracer.core;

/**
 * How much of the ray tree a render traces: the report's term pass ({@link ShadingPass}, figures 4
 * and 6) and the adaptive cutoff of Hall and Greenberg (1983). One value for the whole render, read
 * from the scene file and the command line; each worker turns it into its own {@link RayTreePolicy},
 * which also records the path weights as the recursion descends.
 *
 * @param pass which terms the first hit shows; {@link ShadingPass#FULL} normally
 * @param cutoff branches whose path weight is below it in every channel are not traced, light
 *        samples that would add less than it (in display units) are not shadow-tested, and hits
 *        below the camera's take area-light samples in proportion to their weight; 0 traces the
 *        whole tree to the view plane's max depth
 */
public record RayTreeSettings(ShadingPass pass, double cutoff) {
    /** Every term, the whole tree: the settings of a scene that names neither. */
    public static final RayTreeSettings FULL_TREE = new RayTreeSettings(ShadingPass.FULL, 0);

    public RayTreeSettings {
        if (pass == null) {
            throw new IllegalArgumentException("a shading pass is needed");
        }
        if (!(cutoff >= 0 && cutoff < 1)) {
            throw new IllegalArgumentException("cutoff must be in [0, 1), got " + cutoff);
        }
    }

    public RayTreeSettings withPass(ShadingPass pass) {
        return new RayTreeSettings(pass, cutoff);
    }

    public RayTreeSettings withCutoff(double cutoff) {
        return new RayTreeSettings(pass, cutoff);
    }
}
