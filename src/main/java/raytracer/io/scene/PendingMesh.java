package raytracer.io.scene;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import raytracer.accel.MeshBVH;
import raytracer.core.GeometricObject;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Ray;

/**
 * A mesh object as loaded, before {@link raytracer.core.World#prepare}: its bounds and materials
 * are known, for the scene analysis, but its BVH is not built yet. Preparing it makes the
 * {@link MeshBVH} it is rendered as, read from the mesh cache or built over the parsed mesh, once
 * however many instances share it; a mesh that the analysis leaves out is never made.
 */
final class PendingMesh extends GeometricObject {
    /** Makes the mesh object: reads or builds it, and says so in the load report. */
    interface Maker {
        MeshBVH make() throws SceneException;
    }

    private final String description;
    private final BBox bounds;
    private final List<Material> faceMaterials;
    private final Maker maker;
    private MeshBVH prepared;

    /** {@code bounds}: of the mesh's vertices; {@code faceMaterials}: per material id, null entries falling back to the object's. */
    PendingMesh(String description, BBox bounds, List<Material> faceMaterials, Maker maker) {
        this.description = description;
        this.bounds = bounds;
        this.faceMaterials = faceMaterials.stream().filter(Objects::nonNull).toList();
        this.maker = maker;
    }

    /**
     * The mesh object, made on the first call; it takes this object's material and shadow setting.
     * A failure (the OBJ file unreadable after all) is an IllegalStateException with the message.
     */
    @Override
    public synchronized GeometricObject prepared() {
        if (prepared == null) {
            try {
                prepared = maker.make();
            } catch (SceneException e) {
                throw new IllegalStateException(e.getMessage(), e);
            }
            prepared.setMaterial(getMaterial());
            prepared.setCastsShadows(castsShadows());
        }
        return prepared;
    }

    @Override
    public List<Material> materials() {
        Set<Material> all = new LinkedHashSet<>(super.materials());
        all.addAll(faceMaterials);
        return List.copyOf(all);
    }

    @Override
    public String description() {
        return description;
    }

    /** The box of the vertices: tighter than the BVH's, whose boxes are rounded outward to floats. */
    @Override
    public BBox boundingBox() {
        return bounds;
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        throw notPrepared();
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        throw notPrepared();
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        throw notPrepared();
    }

    private IllegalStateException notPrepared() {
        return new IllegalStateException(description + " is traced before World.prepare built it");
    }
}
