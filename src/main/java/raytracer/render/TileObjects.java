package raytracer.render;

import java.util.ArrayList;
import java.util.List;
import raytracer.core.Camera;
import raytracer.core.GeometricObject;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.math.HalfSpace;

/**
 * For each tile, the objects its camera rays can hit, as they can hit them
 * ({@link GeometricObject#within} the volume that holds every camera ray through the tile's
 * pixels, {@link Camera#viewVolume(ViewPlane, double, double, double, double)}): an object whose
 * box a face of that volume wholly excludes (by {@link HalfSpace#excludes}'s margin, a million
 * times the rounding of a computed ray) is left out, and a BVH is searched from the subtree that
 * holds all the tile can reach. Screen-space culling in the manner of a first-hit grid: on a
 * scene of a few objects most tiles see one or two of them, and the other tests could only miss.
 */
final class TileObjects {
    private TileObjects() {
    }

    /**
     * Per tile of {@code tiles} (x0, y0, x1, y1), the objects of {@link World#searched} in their
     * order that its camera rays can hit, as they can hit them, or null where that is all of them
     * as they are; null altogether when the world does not search by tile.
     */
    static GeometricObject[][] of(World world, List<int[]> tiles) {
        return of(world, tiles, null);
    }

    /** As above, for the tiles of {@code indices} alone (null: all); the others' entries stay null. */
    static GeometricObject[][] of(World world, List<int[]> tiles, int[] indices) {
        if (!world.searchesByTile()) {
            return null;
        }
        List<GeometricObject> searched = world.searched();
        ViewPlane vp = world.viewPlane();
        Camera camera = world.camera();
        GeometricObject[][] perTile = new GeometricObject[tiles.size()][];
        for (int k = 0; k < (indices == null ? perTile.length : indices.length); k++) {
            int i = indices == null ? k : indices[k];
            int[] tile = tiles.get(i);
            List<HalfSpace> volume = camera.viewVolume(vp, tile[0], tile[1], tile[2], tile[3]);
            List<GeometricObject> seen = new ArrayList<>();
            boolean same = true;
            for (GeometricObject object : searched) {
                GeometricObject view = object.within(volume);
                same &= view == object;
                if (view != null) {
                    seen.add(view);
                }
            }
            perTile[i] = same ? null : seen.toArray(new GeometricObject[0]);
        }
        return perTile;
    }
}
