package raytracer.shapes;

import java.util.ArrayList;
import java.util.List;
import raytracer.core.GeometricObject;
import raytracer.core.LocalFrame;
import raytracer.core.Material;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;
import raytracer.math.Matrix4;
import raytracer.math.Ray;
import raytracer.math.Rounding;

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
    /** How far the inverse's linear part may be from the exact one ({@link Matrix4#inverseError}). */
    private final double inverseError;
    /** The infinity norm of the inverse's linear part. */
    private final double inverseNorm;
    /** The largest magnitude of the matrix's translation, and of the inverse's. */
    private final double translation;
    private final double inverseTranslation;

    public Instance(GeometricObject object, Matrix4 transform) {
        this(object, transform, transform.inverse());
    }

    private Instance(GeometricObject object, Matrix4 forward, Matrix4 inverse) {
        this.object = object;
        this.forward = forward;
        this.inverse = inverse;
        // a matrix too ill-conditioned for any bound (rho infinite): its object is tested as if the ray were exact
        double rho = forward.inverseError(inverse);
        this.inverseError = Double.isFinite(rho) ? rho : 0;
        this.inverseNorm = norm(inverse);
        this.translation = Math.max(Math.abs(forward.get(0, 3)), Math.max(Math.abs(forward.get(1, 3)), Math.abs(forward.get(2, 3))));
        this.inverseTranslation = Math.max(Math.abs(inverse.get(0, 3)), Math.max(Math.abs(inverse.get(1, 3)), Math.abs(inverse.get(2, 3))));
    }

    /** The object this instance moves, in its own space. */
    public GeometricObject object() {
        return object;
    }

    /** The same instance of the object prepared, when preparing made a new one (a mesh's BVH). */
    @Override
    public GeometricObject prepared() {
        GeometricObject inner = object.prepared();
        return inner == object ? this : around(inner);
    }

    /** This instance's matrices, material and shadow setting around another object: its prepared form or a view of it. */
    private Instance around(GeometricObject inner) {
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

    /**
     * The object as rays in {@code volume} can hit it, asked in its own space: a point q there is
     * M q = A q + t in the world, so the face n . p &lt;= d is (A^T n) . q &lt;= d - n . t. The
     * object sees the ray as the inverse matrix computes it, off the exact one by rounding that
     * grows with the condition of A; the faces' size is raised to match (|A| |A^-1|^2 times the
     * largest coordinate involved), so that their margin covers it. When the object narrows its
     * search, this returns an instance of that view under the same matrices.
     */
    @Override
    public GeometricObject within(List<HalfSpace> volume) {
        if (super.within(volume) == null) {
            return null;
        }
        double a = norm(forward);
        double aInverse = norm(inverse);
        double reach = Math.max(boundingBox().maxAbs(), translation);
        List<HalfSpace> local = new ArrayList<>(volume.size());
        for (HalfSpace face : volume) {
            double nx = forward.get(0, 0) * face.nx() + forward.get(1, 0) * face.ny() + forward.get(2, 0) * face.nz();
            double ny = forward.get(0, 1) * face.nx() + forward.get(1, 1) * face.ny() + forward.get(2, 1) * face.nz();
            double nz = forward.get(0, 2) * face.nx() + forward.get(1, 2) * face.ny() + forward.get(2, 2) * face.nz();
            double d = face.d() - (face.nx() * forward.get(0, 3) + face.ny() * forward.get(1, 3) + face.nz() * forward.get(2, 3));
            if (nx == 0 && ny == 0 && nz == 0 || !Double.isFinite(nx + ny + nz + d)) {
                return this;
            }
            double size = a * aInverse * aInverse * Math.max(face.size(), reach);
            if (!Double.isFinite(size)) {
                return this;
            }
            local.add(new HalfSpace(nx, ny, nz, d, size));
        }
        GeometricObject inner = object.within(local);
        return inner == object ? this : inner == null ? null : around(inner);
    }

    /** The sum of magnitudes of row {@code row} of the matrix's linear part. */
    private double rowSum(int row) {
        return Math.abs(forward.get(row, 0)) + Math.abs(forward.get(row, 1)) + Math.abs(forward.get(row, 2));
    }

    /** The infinity norm of the matrix's linear part: its largest row sum of magnitudes. */
    private static double norm(Matrix4 m) {
        double largest = 0;
        for (int row = 0; row < 3; row++) {
            largest = Math.max(largest, Math.abs(m.get(row, 0)) + Math.abs(m.get(row, 1)) + Math.abs(m.get(row, 2)));
        }
        return largest;
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
        setErrors(ray, local);
        boolean hit = object.shadowHit(local, tMax, sr);
        sr.releaseLocalRay();
        return hit;
    }

    /**
     * Bounds how far the object-space ray is from the exact inverse image of {@code ray}, so that
     * the object's shadow test widens its bounds on t by them: the origin by {@link #localError},
     * the direction by the inverse's error and one product's rounding, (rho + gamma(3)) |A~| |d|
     * (no translation), and the world ray's own errors carried through A~.
     */
    private void setErrors(Ray world, Ray local) {
        double direction = Math.max(Math.abs(world.dx), Math.max(Math.abs(world.dy), Math.abs(world.dz)));
        double grow = 1 + Rounding.gamma(3);
        double originError = grow * inverseNorm * world.originError + localError(world.ox, world.oy, world.oz);
        double directionError = grow * inverseNorm * world.directionError + (inverseError + Rounding.gamma(3)) * inverseNorm * direction;
        local.setErrors(originError, directionError);
    }

    /**
     * How far, on every axis, the object-space image of the world point p computed through the
     * inverse may be from the exact one: A~ p + t~ against A^-1 (p - t), off by the inverse's error
     * and the rounding of both products, (rho + gamma(4)) (|A~| (|p| + |t|) + |t~|), bounded with
     * infinity norms.
     */
    private double localError(double px, double py, double pz) {
        double p = Math.max(Math.abs(px), Math.max(Math.abs(py), Math.abs(pz)));
        return (inverseError + Rounding.gamma(4)) * (inverseNorm * (p + translation) + inverseTranslation);
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        throw new IllegalStateException("an instance is completed through its LocalFrame, never as a leaf");
    }

    @Override
    public void toLocal(Ray in, Ray out) {
        inverse.transformRay(in, out);
    }

    /**
     * Brings the completed hit to the world: the point and its error bound through the matrix
     * (pbrt-v3, eq. 3.16), widened on every axis by what a ray leaving the point adds on its way
     * back into the object's space ({@link #localError}, through A): the offset that
     * ShadeRec.spawnRay takes from this bound must clear the object's surface as the inverse
     * computes it, or a sphere turned, stretched and moved 3e4 away finds itself again (0.9% of
     * spawned rays before).
     */
    @Override
    public void toWorld(ShadeRec sr) {
        forward.transformPointError(sr.hitPoint, sr.hitError);
        forward.transformPoint(sr.hitPoint);
        double back = localError(sr.hitPoint.x, sr.hitPoint.y, sr.hitPoint.z) * (1 + Rounding.gamma(3));
        if (Double.isFinite(back)) {
            sr.hitError.set(sr.hitError.x + rowSum(0) * back, sr.hitError.y + rowSum(1) * back, sr.hitError.z + rowSum(2) * back);
        }
        inverse.transformNormalByInverse(sr.normal);
        inverse.transformNormalByInverse(sr.geometricNormal);
        if (getMaterial() != null) {
            sr.material = getMaterial();
        }
    }

    /** The instance's own material replaces the object's, when it has one. */
    @Override
    public boolean usesTextureCoordinates() {
        return getMaterial() != null ? getMaterial().needs().textureCoordinates() : object.usesTextureCoordinates();
    }

    @Override
    public BBox boundingBox() {
        BBox box = object.boundingBox();
        if (box.isBounded()) {
            return forward.transform(box);
        }
        // an unbounded box (a plane's slab, say) turned by the transform bounds nothing narrower than space
        double inf = Double.POSITIVE_INFINITY;
        return new BBox(-inf, -inf, -inf, inf, inf, inf);
    }
}
