package raytracer.shapes;

import java.util.List;
import raytracer.core.GeometricObject;
import raytracer.core.LocalFrame;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Matrix4;
import raytracer.math.Ray;

/**
 * An object under an affine transform (Suffern, chapter 21): the ray is taken into the object's
 * space by the inverse matrix, and the completed hit is brought back. Directions are not
 * renormalised, so t is the same in both spaces. A material set on the instance overrides the
 * object's.
 */
public final class Instance extends GeometricObject implements LocalFrame {
    private final GeometricObject object;
    private final Matrix4 forward;
    private final Matrix4 inverse;

    public Instance(GeometricObject object, Matrix4 transform) {
        this(object, transform, transform.inverse());
    }

    private Instance(GeometricObject object, Matrix4 forward, Matrix4 inverse) {
        this.object = object;
        this.forward = forward;
        this.inverse = inverse;
    }

    /** The same instance of the object prepared, when preparing made a new one (a mesh's BVH). */
    @Override
    public GeometricObject prepared() {
        GeometricObject inner = object.prepared();
        if (inner == object) {
            return this;
        }
        Instance copy = new Instance(inner, forward, inverse);
        copy.setMaterial(getMaterial());
        copy.setCastsShadows(castsShadows());
        return copy;
    }

    /** The instance's own material when it has one (it overrides the object's), else the object's. */
    @Override
    public List<Material> materials() {
        return getMaterial() != null ? List.of(getMaterial()) : object.materials();
    }

    @Override
    public String description() {
        return "instance of " + object.description();
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        Ray local = sr.borrowLocalRay();
        inverse.transformRay(ray, local);
        boolean hit = object.hit(local, sr);
        sr.releaseLocalRay();
        if (hit) {
            sr.pushTransform(this);
        }
        return hit;
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        Ray local = sr.borrowLocalRay();
        inverse.transformRay(ray, local);
        boolean hit = object.shadowHit(local, tMax, sr);
        sr.releaseLocalRay();
        return hit;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        throw new IllegalStateException("an instance is completed through its LocalFrame, never as a leaf");
    }

    @Override
    public void toLocal(Ray in, Ray out) {
        inverse.transformRay(in, out);
    }

    @Override
    public void toWorld(ShadeRec sr) {
        forward.transformPointError(sr.hitPoint, sr.hitError);
        forward.transformPoint(sr.hitPoint);
        inverse.transformNormalByInverse(sr.normal);
        inverse.transformNormalByInverse(sr.geometricNormal);
        if (getMaterial() != null) {
            sr.material = getMaterial();
        }
    }

    /** The instance's own material replaces the object's, when it has one. */
    @Override
    public boolean usesTextureCoordinates() {
        return getMaterial() != null ? getMaterial().usesTextureCoordinates() : object.usesTextureCoordinates();
    }

    @Override
    public BBox boundingBox() {
        BBox box = object.boundingBox();
        return box.isBounded() ? forward.transform(box) : box;
    }
}
