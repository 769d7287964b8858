package raytracer.io.obj;

import java.nio.file.Path;

/**
 * The values of one {@code newmtl} of an MTL file, as written (the caller maps them onto its own
 * materials). Colours are RGB triples; texture paths are resolved and exist, or are null.
 */
public record ObjMaterial(String name, double[] kd, double[] ks, double[] ka, double[] ke, double ns,
                          double dissolve, double ior, int illum, Path mapKd, Path mapBump, double bumpScale) {

    /** Whether light passes through it: d below 1 (or Tr above 0; d wins when both are given). */
    public boolean seeThrough() {
        return dissolve < 1;
    }

    /** The material of faces that name none, or name one no MTL file defines: grey, diffuse. */
    static ObjMaterial fallback(String name) {
        return new ObjMaterial(name, new double[] {0.8, 0.8, 0.8}, new double[3], new double[3], new double[3],
                               0, 1, 1, 1, null, null, 1);
    }
}
