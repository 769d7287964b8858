package raytracer.accel;

import java.util.List;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.math.BBox;
import raytracer.math.Ray;

/**
 * Reference solution of exercise 6 (docs/teaching.md): a regular grid over bounded objects
 * (Suffern, chapter 22). The box of all objects is cut into about {@value #DENSITY} N cells,
 * nearly cubic; each cell lists the objects whose boxes overlap it. A ray walks the cells it
 * pierces in order (Amanatides and Woo 1987) and tests their objects; once the closest hit so far
 * lies within the cells walked, no later cell can hold a closer one.
 */
public final class RegularGrid extends GeometricObject {
    /** Cells per object: Suffern's multiplier m = 2 per axis, 8 cells an object. */
    private static final int DENSITY = 8;
    private final BBox box;
    private final int nx;
    private final int ny;
    private final int nz;
    /** The objects of cell c are objects[cellObjects[k]] for k in cellStart[c] .. cellStart[c + 1] - 1. */
    private final int[] cellStart;
    private final int[] cellObjects;
    private final GeometricObject[] objects;

    public RegularGrid(List<GeometricObject> list) {
        objects = list.toArray(new GeometricObject[0]);
        if (objects.length == 0) {
            throw new IllegalArgumentException("a grid needs at least one object");
        }
        BBox all = BBox.EMPTY;
        for (GeometricObject o : objects) {
            BBox b = o.boundingBox();
            if (!b.isBounded()) {
                throw new IllegalArgumentException("an unbounded object (a plane) cannot go in a grid");
            }
            all = all.union(b);
        }
        box = all;
        // cells of side s with nx ny nz ~ DENSITY N (Suffern, chapter 22); a flat side gets one layer
        double wx = box.x1() - box.x0();
        double wy = box.y1() - box.y0();
        double wz = box.z1() - box.z0();
        double largest = Math.max(wx, Math.max(wy, wz));
        double volume = Math.max(wx, 1e-3 * largest) * Math.max(wy, 1e-3 * largest) * Math.max(wz, 1e-3 * largest);
        double s = Math.cbrt(volume / (DENSITY * (double) objects.length));
        nx = cells(wx, s);
        ny = cells(wy, s);
        nz = cells(wz, s);
        // two passes: count each cell's objects, then place them
        cellStart = new int[nx * ny * nz + 1];
        for (GeometricObject o : objects) {
            forEachCell(o.boundingBox(), (c, unused) -> cellStart[c + 1]++);
        }
        for (int c = 0; c < nx * ny * nz; c++) {
            cellStart[c + 1] += cellStart[c];
        }
        cellObjects = new int[cellStart[nx * ny * nz]];
        int[] filled = new int[nx * ny * nz];
        for (int i = 0; i < objects.length; i++) {
            forEachCell(objects[i].boundingBox(), (c, index) -> cellObjects[cellStart[c] + filled[c]++] = index, i);
        }
    }

    private static int cells(double width, double side) {
        return (int) Math.max(1, Math.min(256, Math.floor(width / side) + 1));
    }

    private interface CellAction {
        void apply(int cell, int object);
    }

    private void forEachCell(BBox b, CellAction action) {
        forEachCell(b, action, -1);
    }

    private void forEachCell(BBox b, CellAction action, int object) {
        int x0 = index(b.x0(), box.x0(), box.x1(), nx);
        int x1 = index(b.x1(), box.x0(), box.x1(), nx);
        int y0 = index(b.y0(), box.y0(), box.y1(), ny);
        int y1 = index(b.y1(), box.y0(), box.y1(), ny);
        int z0 = index(b.z0(), box.z0(), box.z1(), nz);
        int z1 = index(b.z1(), box.z0(), box.z1(), nz);
        for (int z = z0; z <= z1; z++) {
            for (int y = y0; y <= y1; y++) {
                for (int x = x0; x <= x1; x++) {
                    action.apply(x + nx * (y + ny * z), object);
                }
            }
        }
    }

    /** The cell along one axis holding coordinate v, clamped to the grid. */
    private static int index(double v, double lo, double hi, int n) {
        if (!(hi > lo)) {
            return 0;
        }
        return (int) Math.max(0, Math.min(n - 1, Math.floor((v - lo) / (hi - lo) * n)));
    }

    @Override
    public boolean hit(Ray ray, ShadeRec sr) {
        return walk(ray, sr, sr.t, false);
    }

    @Override
    public boolean shadowHit(Ray ray, double tMax, ShadeRec sr) {
        return walk(ray, sr, tMax, true);
    }

    /**
     * Walks the cells the ray pierces up to tMax. For a closest hit, tests every object of each cell
     * and stops once sr.t, the closest hit so far, lies before the cell's exit; for a shadow ray,
     * stops at the first shadow-casting object that blocks it.
     */
    private boolean walk(Ray ray, ShadeRec sr, double tMax, boolean shadow) {
        // the slabs of the grid's box: where the ray enters and leaves each, and the box
        double txMin = slabEntry(ray.ox, ray.dx, box.x0(), box.x1());
        double txMax = slabExit(ray.ox, ray.dx, box.x0(), box.x1());
        double tyMin = slabEntry(ray.oy, ray.dy, box.y0(), box.y1());
        double tyMax = slabExit(ray.oy, ray.dy, box.y0(), box.y1());
        double tzMin = slabEntry(ray.oz, ray.dz, box.z0(), box.z1());
        double tzMax = slabExit(ray.oz, ray.dz, box.z0(), box.z1());
        double t0 = Math.max(txMin, Math.max(tyMin, tzMin));
        double t1 = Math.min(txMax, Math.min(tyMax, tzMax));
        if (!(t0 <= t1) || t1 < 0 || t0 >= tMax) {
            return false;
        }
        // the first cell: the one holding the origin, or the entry point
        double start = Math.max(t0, 0);
        int ix = index(ray.ox + start * ray.dx, box.x0(), box.x1(), nx);
        int iy = index(ray.oy + start * ray.dy, box.y0(), box.y1(), ny);
        int iz = index(ray.oz + start * ray.dz, box.z0(), box.z1(), nz);
        // per axis: the distance between cell walls, the next wall, the step and where the walk ends
        double dtx = (txMax - txMin) / nx;
        double dty = (tyMax - tyMin) / ny;
        double dtz = (tzMax - tzMin) / nz;
        double txNext = ray.dx > 0 ? txMin + (ix + 1) * dtx : ray.dx < 0 ? txMin + (nx - ix) * dtx : Double.POSITIVE_INFINITY;
        double tyNext = ray.dy > 0 ? tyMin + (iy + 1) * dty : ray.dy < 0 ? tyMin + (ny - iy) * dty : Double.POSITIVE_INFINITY;
        double tzNext = ray.dz > 0 ? tzMin + (iz + 1) * dtz : ray.dz < 0 ? tzMin + (nz - iz) * dtz : Double.POSITIVE_INFINITY;
        int stepX = ray.dx > 0 ? 1 : -1;
        int stepY = ray.dy > 0 ? 1 : -1;
        int stepZ = ray.dz > 0 ? 1 : -1;
        boolean hit = false;
        while (true) {
            int cell = ix + nx * (iy + ny * iz);
            for (int k = cellStart[cell]; k < cellStart[cell + 1]; k++) {
                GeometricObject o = objects[cellObjects[k]];
                if (shadow) {
                    if (o.castsShadows() && o.shadowHit(ray, tMax, sr)) {
                        return true;
                    }
                } else {
                    hit |= o.hit(ray, sr);
                }
            }
            double exit = Math.min(txNext, Math.min(tyNext, tzNext));
            if ((shadow ? tMax : sr.t) <= exit) {
                return hit;
            }
            if (txNext == exit) {
                ix += stepX;
                txNext += dtx;
                if (ix < 0 || ix == nx) {
                    return hit;
                }
            } else if (tyNext == exit) {
                iy += stepY;
                tyNext += dty;
                if (iy < 0 || iy == ny) {
                    return hit;
                }
            } else {
                iz += stepZ;
                tzNext += dtz;
                if (iz < 0 || iz == nz) {
                    return hit;
                }
            }
        }
    }

    /** Where the ray enters the slab lo..hi; -infinity when it runs inside it, +infinity when outside. */
    private static double slabEntry(double o, double d, double lo, double hi) {
        if (d == 0) {
            return o >= lo && o <= hi ? Double.NEGATIVE_INFINITY : Double.POSITIVE_INFINITY;
        }
        return ((d > 0 ? lo : hi) - o) / d;
    }

    /** Where the ray leaves the slab lo..hi; +infinity when it runs inside it, -infinity when outside. */
    private static double slabExit(double o, double d, double lo, double hi) {
        if (d == 0) {
            return o >= lo && o <= hi ? Double.POSITIVE_INFINITY : Double.NEGATIVE_INFINITY;
        }
        return ((d > 0 ? hi : lo) - o) / d;
    }

    @Override
    public void completeHit(Ray ray, ShadeRec sr) {
        throw new IllegalStateException("a grid is never the leaf of a hit; its objects are");
    }

    @Override
    public BBox boundingBox() {
        return box;
    }
}
