package raytracer.accel;

import java.util.List;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Ray;

/**
 * A BVH over ordinary bounded objects (spheres, instances, meshes): the objects' own {@code hit}
 * methods record the closest hit, so completion goes straight to the leaf that won.
 */
public final class ObjectBVH extends GeometricObject implements Leaves, StartedSearch {
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
        return bvh.closestHit(ray, sr, this);
    }

    @Override
    public GeometricObject within(List<HalfSpace> volume) {
        return SubtreeSearch.of(this, bvh, volume);
    }

    @Override
    public boolean hit(FlatBVH.Start start, Ray ray, ShadeRec sr) {
        return bvh.closestHit(start, ray, sr, this);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return bvh.anyHit(ray, tMax, sr, this);
    }

    @Override
    public boolean hit(int first, int count, Ray ray, ShadeRec sr) {
        boolean hit = false;
        for (int k = first; k < first + count; k++) {
            hit |= objects[k].hit(ray, sr);
        }
        return hit;
    }

    @Override
    public boolean shadowHit(int first, int count, Ray ray, double tMax, ShadeRec sr) {
        for (int k = first; k < first + count; k++) {
            if (castsShadows[k] && objects[k].shadowHit(ray, tMax, sr)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        throw new IllegalStateException("a BVH is never the leaf of a hit; its objects are");
    }

    @Override
    public BBox boundingBox() {
        return new BBox(bvh.rootBound(0), bvh.rootBound(1), bvh.rootBound(2),
                        bvh.rootBound(3), bvh.rootBound(4), bvh.rootBound(5));
    }

    public FlatBVH bvh() {
        return bvh;
    }
}
