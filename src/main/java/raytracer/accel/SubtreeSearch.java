package raytracer.accel;

import java.util.List;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Ray;

/**
 * An aggregate as the camera rays of one tile see it ({@link GeometricObject#within}): their
 * closest-hit search starts in the subtree that holds all they can reach, skipping the box tests
 * above it, which could only have led there. Hits are recorded as the aggregate's search records
 * them (the mesh, or the leaf object), so the view itself is never completed or shaded; what else
 * is asked of it, the aggregate answers.
 */
final class SubtreeSearch extends GeometricObject {
    private final GeometricObject whole;
    private final StartedSearch search;
    private final FlatBVH.Start start;

    private <T extends GeometricObject & StartedSearch> SubtreeSearch(T whole, FlatBVH.Start start) {
        this.whole = whole;
        this.search = whole;
        this.start = start;
    }

    /**
     * {@code whole} (searched by {@code bvh}) as rays in {@code volume} can hit it: null when they
     * reach none of its leaves, itself when their search starts at the root, else a view whose
     * search starts in the subtree {@link FlatBVH#startFor} finds.
     */
    static <T extends GeometricObject & StartedSearch> GeometricObject of(T whole, FlatBVH bvh, List<HalfSpace> volume) {
        FlatBVH.Start start = bvh.startFor(volume);
        return start == null ? null : start == bvh.root ? whole : new SubtreeSearch(whole, start);
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return search.hit(start, ray, sr);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return whole.shadowHit(ray, tMax, sr);
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        whole.completeHit(ray, sr);
    }

    @Override
    public BBox boundingBox() {
        return whole.boundingBox();
    }

    @Override
    public List<Material> materials() {
        return whole.materials();
    }

    @Override
    public String description() {
        return whole.description();
    }
}
