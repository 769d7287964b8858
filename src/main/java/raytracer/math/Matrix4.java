package raytracer.math;

import java.util.Arrays;

/**
 * An immutable 4x4 affine matrix, row-major (Suffern, chapter 20). Points take the translation,
 * vectors do not, and normals transform by the inverse transpose.
 */
public final class Matrix4 {
    public static final Matrix4 IDENTITY = new Matrix4(new double[] {
        1, 0, 0, 0,
        0, 1, 0, 0,
        0, 0, 1, 0,
        0, 0, 0, 1});

    private final double[] m;

    private Matrix4(double[] m) {
        this.m = m;
    }

    public static Matrix4 of(double... rowMajor16) {
        if (rowMajor16.length != 16) {
            throw new IllegalArgumentException("a 4x4 matrix needs 16 numbers, got " + rowMajor16.length);
        }
        return new Matrix4(rowMajor16.clone());
    }

    public static Matrix4 translate(double tx, double ty, double tz) {
        return new Matrix4(new double[] {1, 0, 0, tx, 0, 1, 0, ty, 0, 0, 1, tz, 0, 0, 0, 1});
    }

    public static Matrix4 scale(double sx, double sy, double sz) {
        return new Matrix4(new double[] {sx, 0, 0, 0, 0, sy, 0, 0, 0, 0, sz, 0, 0, 0, 0, 1});
    }

    public static Matrix4 rotateX(double degrees) {
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        return new Matrix4(new double[] {1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0, 0, 0, 0, 1});
    }

    public static Matrix4 rotateY(double degrees) {
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        return new Matrix4(new double[] {c, 0, s, 0, 0, 1, 0, 0, -s, 0, c, 0, 0, 0, 0, 1});
    }

    public static Matrix4 rotateZ(double degrees) {
        double c = Math.cos(Math.toRadians(degrees));
        double s = Math.sin(Math.toRadians(degrees));
        return new Matrix4(new double[] {c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
    }

    public double get(int row, int col) {
        return m[4 * row + col];
    }

    /** this * other: {@code other} is applied first. */
    public Matrix4 multiply(Matrix4 other) {
        double[] r = new double[16];
        for (int i = 0; i < 4; i++) {
            for (int j = 0; j < 4; j++) {
                double s = 0;
                for (int k = 0; k < 4; k++) {
                    s += m[4 * i + k] * other.m[4 * k + j];
                }
                r[4 * i + j] = s;
            }
        }
        return new Matrix4(r);
    }

    public double determinant3x3() {
        return m[0] * (m[5] * m[10] - m[6] * m[9])
             - m[1] * (m[4] * m[10] - m[6] * m[8])
             + m[2] * (m[4] * m[9] - m[5] * m[8]);
    }

    /** Inverse of an affine matrix: invert the 3x3 part by cofactors, then the translation. */
    public Matrix4 inverse() {
        double det = determinant3x3();
        if (det == 0 || !Double.isFinite(det)) {
            throw new IllegalArgumentException("the transform is singular (determinant " + det + ")");
        }
        double d = 1.0 / det;
        double[] r = new double[16];
        r[0] = (m[5] * m[10] - m[6] * m[9]) * d;
        r[1] = (m[2] * m[9] - m[1] * m[10]) * d;
        r[2] = (m[1] * m[6] - m[2] * m[5]) * d;
        r[4] = (m[6] * m[8] - m[4] * m[10]) * d;
        r[5] = (m[0] * m[10] - m[2] * m[8]) * d;
        r[6] = (m[2] * m[4] - m[0] * m[6]) * d;
        r[8] = (m[4] * m[9] - m[5] * m[8]) * d;
        r[9] = (m[1] * m[8] - m[0] * m[9]) * d;
        r[10] = (m[0] * m[5] - m[1] * m[4]) * d;
        r[3] = -(r[0] * m[3] + r[1] * m[7] + r[2] * m[11]);
        r[7] = -(r[4] * m[3] + r[5] * m[7] + r[6] * m[11]);
        r[11] = -(r[8] * m[3] + r[9] * m[7] + r[10] * m[11]);
        r[15] = 1;
        return new Matrix4(r);
    }

    /**
     * A bound rho on how far {@code inverse}, this matrix's inverse as computed, is from the exact
     * one in its linear part A: for every vector y, |(A~ - A^-1) y|_i <= rho max_k (|A~| |y|)_k.
     * With R = A~ A - I, A^-1 = (I + R)^-1 A~, so rho = r / (1 - r) with r the infinity norm of R,
     * taken from R as computed plus the rounding of computing it (gamma(4) |A~| |A|). Infinite when
     * r &gt;= 1: the inverse is then no closer than its own size.
     */
    public double inverseError(Matrix4 inverse) {
        double r = 0;
        for (int i = 0; i < 3; i++) {
            double row = 0;
            for (int j = 0; j < 3; j++) {
                double s = 0;
                double magnitude = 0;
                for (int k = 0; k < 3; k++) {
                    s += inverse.m[4 * i + k] * m[4 * k + j];
                    magnitude += Math.abs(inverse.m[4 * i + k] * m[4 * k + j]);
                }
                row += Math.abs(s - (i == j ? 1 : 0)) + Rounding.gamma(4) * magnitude;
            }
            r = Math.max(r, row);
        }
        return r < 1 ? r / (1 - r) : Double.POSITIVE_INFINITY;
    }

    public Point3D transform(Point3D p) {
        return new Point3D(
            m[0] * p.x() + m[1] * p.y() + m[2] * p.z() + m[3],
            m[4] * p.x() + m[5] * p.y() + m[6] * p.z() + m[7],
            m[8] * p.x() + m[9] * p.y() + m[10] * p.z() + m[11]);
    }

    public Vector3D transform(Vector3D v) {
        return new Vector3D(
            m[0] * v.x() + m[1] * v.y() + m[2] * v.z(),
            m[4] * v.x() + m[5] * v.y() + m[6] * v.z(),
            m[8] * v.x() + m[9] * v.y() + m[10] * v.z());
    }

    /** Applies this matrix to the point {@code p} in place. */
    public void transformPoint(MutableVec3 p) {
        p.set(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3],
              m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
              m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
    }

    /** Applies this matrix to the vector {@code v} in place (no translation). */
    public void transformVector(MutableVec3 v) {
        v.set(m[0] * v.x + m[1] * v.y + m[2] * v.z,
              m[4] * v.x + m[5] * v.y + m[6] * v.z,
              m[8] * v.x + m[9] * v.y + m[10] * v.z);
    }

    /**
     * Transforms a normal in place when this matrix is the <em>inverse</em> of the object's transform:
     * n' = (M^-1)^T n, so the columns of this matrix are used as rows.
     */
    public void transformNormalByInverse(MutableVec3 n) {
        n.set(m[0] * n.x + m[4] * n.y + m[8] * n.z,
              m[1] * n.x + m[5] * n.y + m[9] * n.z,
              m[2] * n.x + m[6] * n.y + m[10] * n.z);
    }

    /** Transforms the ray {@code in} into {@code out} (direction not renormalised, so t is preserved). */
    public void transformRay(Ray in, Ray out) {
        out.set(m[0] * in.ox + m[1] * in.oy + m[2] * in.oz + m[3],
                m[4] * in.ox + m[5] * in.oy + m[6] * in.oz + m[7],
                m[8] * in.ox + m[9] * in.oy + m[10] * in.oz + m[11],
                m[0] * in.dx + m[1] * in.dy + m[2] * in.dz,
                m[4] * in.dx + m[5] * in.dy + m[6] * in.dz,
                m[8] * in.dx + m[9] * in.dy + m[10] * in.dz);
    }

    /**
     * Transforms a point-error bound through this matrix (pbrt-v3, eq. 3.16):
     * |M| e (1 + gamma(3)) + gamma(3) |M| |p|, written into {@code err}.
     */
    public void transformPointError(MutableVec3 p, MutableVec3 err) {
        double g3 = Rounding.gamma(3);
        double ex = Math.abs(m[0]) * err.x + Math.abs(m[1]) * err.y + Math.abs(m[2]) * err.z;
        double ey = Math.abs(m[4]) * err.x + Math.abs(m[5]) * err.y + Math.abs(m[6]) * err.z;
        double ez = Math.abs(m[8]) * err.x + Math.abs(m[9]) * err.y + Math.abs(m[10]) * err.z;
        double px = Math.abs(m[0] * p.x) + Math.abs(m[1] * p.y) + Math.abs(m[2] * p.z) + Math.abs(m[3]);
        double py = Math.abs(m[4] * p.x) + Math.abs(m[5] * p.y) + Math.abs(m[6] * p.z) + Math.abs(m[7]);
        double pz = Math.abs(m[8] * p.x) + Math.abs(m[9] * p.y) + Math.abs(m[10] * p.z) + Math.abs(m[11]);
        err.set((1 + g3) * ex + g3 * px, (1 + g3) * ey + g3 * py, (1 + g3) * ez + g3 * pz);
    }

    /** The bounding box of the transformed corners of {@code b}. */
    public BBox transform(BBox b) {
        BBox result = BBox.EMPTY;
        for (int i = 0; i < 8; i++) {
            Point3D corner = new Point3D((i & 1) == 0 ? b.x0() : b.x1(),
                                         (i & 2) == 0 ? b.y0() : b.y1(),
                                         (i & 4) == 0 ? b.z0() : b.z1());
            result = result.union(transform(corner));
        }
        return result;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Matrix4 other && Arrays.equals(m, other.m);
    }

    @Override
    public int hashCode() {
        return Arrays.hashCode(m);
    }

    @Override
    public String toString() {
        return "Matrix4" + Arrays.toString(m);
    }
}
