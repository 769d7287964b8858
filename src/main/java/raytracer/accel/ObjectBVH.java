package raytracer.accel;

import java.util.List;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Ray;

/**
 * A BVH over ordinary bounded objects (spheres, instances, meshes): the objects' own {@code hit}
 * methods record the closest hit, so completion goes straight to the leaf that won.
 */
public final class ObjectBVH extends GeometricObject {
    private final GeometricObject[] objects;
    private final boolean[] castsShadows;
    private final FlatBVH bvh;

    private ObjectBVH(GeometricObject[] objects, FlatBVH bvh) {
        this.bvh = bvh;
        this.objects = new GeometricObject[objects.length];
        this.castsShadows = new boolean[objects.length];
        for (int k = 0; k < objects.length; k++) {
            this.objects[k] = objects[bvh.order[k]];
            this.castsShadows[k] = this.objects[k].castsShadows();
        }
    }

    /** Builds with the report's median split, or the SAH when {@code sah} is set. */
    public static ObjectBVH build(List<GeometricObject> objects, boolean sah) {
        GeometricObject[] array = objects.toArray(new GeometricObject[0]);
        double[] bounds = new double[6 * array.length];
        for (int i = 0; i < array.length; i++) {
            BBox b = array[i].boundingBox();
            if (!b.isBounded()) {
                throw new IllegalArgumentException("an unbounded object (a plane) cannot go in a BVH");
            }
            bounds[6 * i] = b.x0();
            bounds[6 * i + 1] = b.y0();
            bounds[6 * i + 2] = b.z0();
            bounds[6 * i + 3] = b.x1();
            bounds[6 * i + 4] = b.y1();
            bounds[6 * i + 5] = b.z1();
        }
        FlatBVH bvh = sah ? new SahBuilder(4).build(bounds) : new MedianSplitBuilder(2).build(bounds);
        return new ObjectBVH(array, bvh);
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        int[] stack = sr.traversalStack;
        int base = sr.stackBase;
        int sp = base;
        sr.stackBase = base + FlatBVH.MAX_DEPTH;
        int[] meta = bvh.meta;
        boolean hit = false;
        int node = 0;
        while (true) {
            if (bvh.slab(node, ray, sr.t, sr)) {
                int info = meta[2 * node + 1];
                if (info > 0) {
                    int first = meta[2 * node];
                    for (int k = first; k < first + info; k++) {
                        hit |= objects[k].hit(ray, sr);
                    }
                } else {
                    if (ray.component(-info - 1) < 0) {
                        stack[sp++] = node + 1;
                        node = meta[2 * node];
                    } else {
                        stack[sp++] = meta[2 * node];
                        node = node + 1;
                    }
                    continue;
                }
            }
            if (sp == base) {
                break;
            }
            node = stack[--sp];
        }
        sr.stackBase = base;
        return hit;
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        int[] stack = sr.traversalStack;
        int base = sr.stackBase;
        int sp = base;
        sr.stackBase = base + FlatBVH.MAX_DEPTH;
        int[] meta = bvh.meta;
        int node = 0;
        boolean hit = false;
        while (!hit) {
            if (bvh.slab(node, ray, tMax, sr)) {
                int info = meta[2 * node + 1];
                if (info > 0) {
                    int first = meta[2 * node];
                    for (int k = first; k < first + info && !hit; k++) {
                        hit = castsShadows[k] && objects[k].shadowHit(ray, tMax, sr);
                    }
                } else {
                    stack[sp++] = meta[2 * node];
                    node = node + 1;
                    continue;
                }
            }
            if (sp == base) {
                break;
            }
            node = stack[--sp];
        }
        sr.stackBase = base;
        return hit;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        throw new IllegalStateException("a BVH is never the leaf of a hit; its objects are");
    }

    @Override
    public BBox boundingBox() {
        double[] b = bvh.bounds;
        return new BBox(b[0], b[1], b[2], b[3], b[4], b[5]);
    }

    public FlatBVH bvh() {
        return bvh;
    }
}
