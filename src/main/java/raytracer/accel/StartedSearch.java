package raytracer.accel;

import raytracer.core.ShadeRec;
import raytracer.math.Ray;

/** An aggregate whose closest-hit search can start in a subtree of its {@link FlatBVH}. */
interface StartedSearch {
    /** The closest hit before {@code sr.t} among the leaves below {@code start}, recorded as the aggregate's search records it. */
    boolean hit(FlatBVH.Start start, Ray ray, ShadeRec sr);
}
