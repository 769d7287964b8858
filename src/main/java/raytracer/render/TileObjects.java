package raytracer.render;

import java.util.ArrayList;
import java.util.List;
import raytracer.core.Camera;
import raytracer.core.GeometricObject;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.math.BBox;
import raytracer.math.HalfSpace;

/**
 * For each tile, the objects its camera rays can hit: those not wholly outside a face of the
 * volume that holds every camera ray through the tile's pixels ({@link Camera#viewVolume(ViewPlane,
 * double, double, double, double)}, tested with {@link HalfSpace#excludes}'s margin, a million
 * times the rounding of a computed ray). Screen-space culling in the manner of a first-hit grid:
 * on a scene of a few objects most tiles see one or two of them, and the other tests could only miss.
 */
final class TileObjects {
    private TileObjects() {
    }

    /**
     * Per tile of {@code tiles} (x0, y0, x1, y1), the objects of {@link World#searched} in their
     * order that its camera rays can hit, or null where that is all of them; null altogether when
     * the world does not search by tile.
     */
    static GeometricObject[][] of(World world, List<int[]> tiles) {
        if (!world.searchesByTile()) {
            return null;
        }
        List<GeometricObject> searched = world.searched();
        BBox[] boxes = new BBox[searched.size()];
        for (int k = 0; k < boxes.length; k++) {
            boxes[k] = searched.get(k).boundingBox();
        }
        ViewPlane vp = world.viewPlane();
        Camera camera = world.camera();
        GeometricObject[][] perTile = new GeometricObject[tiles.size()][];
        for (int i = 0; i < perTile.length; i++) {
            int[] tile = tiles.get(i);
            List<HalfSpace> volume = camera.viewVolume(vp, tile[0], tile[1], tile[2], tile[3]);
            List<GeometricObject> seen = new ArrayList<>();
            for (int k = 0; k < boxes.length; k++) {
                if (!outside(boxes[k], volume)) {
                    seen.add(searched.get(k));
                }
            }
            perTile[i] = seen.size() == boxes.length ? null : seen.toArray(new GeometricObject[0]);
        }
        return perTile;
    }

    private static boolean outside(BBox box, List<HalfSpace> volume) {
        for (HalfSpace face : volume) {
            if (face.excludes(box)) {
                return true;
            }
        }
        return false;
    }
}
