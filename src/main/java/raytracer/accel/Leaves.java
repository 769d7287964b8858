package raytracer.accel;

import raytracer.core.ShadeRec;
import raytracer.math.Ray;

/** What a BVH's leaves hold: triangles of a mesh, or objects. */
interface Leaves {

    /** Tests entries first..first+count of the leaf order; records a closer hit in sr; true if any. */
    boolean hit(int first, int count, Ray ray, ShadeRec sr);

    /** True when any of the entries first..first+count blocks the ray on (0, tMax). */
    boolean shadowHit(int first, int count, Ray ray, double tMax, ShadeRec sr);
}
