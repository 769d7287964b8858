package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.cameras.Pinhole;
import raytracer.cameras.ThinLens;
import raytracer.core.Camera;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.lights.Ambient;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Ray;
import raytracer.math.Vector3D;
import raytracer.samplers.Samplers;
import raytracer.shapes.Box;
import raytracer.shapes.Plane;
import raytracer.shapes.Sphere;

/**
 * A tile's camera rays find the same closest hit among the objects its list names as among all:
 * camera rays through random points and the corners of every tile, of random cameras at scales
 * 1e-3 to 1e5 and offsets up to 1e6, over scenes of small spheres and boxes scattered around the
 * view, some grazing the edges of tiles. And the lists are not all of them: most tiles leave out most objects.
 */
class TileObjectsTest {

    @Test
    void everyCameraRayOfATileFindsItsHitAmongTheTilesObjects() {
        SplittableRandom random = new SplittableRandom(21);
        int width = 150;
        int height = 100;
        ViewPlane vp = new ViewPlane(width, height, 1, Samplers.byName("regular"), 0, 1);
        List<int[]> tiles = TileOrder.tiles(width, height);
        long listed = 0;
        long all = 0;
        long hits = 0; // of spheres and boxes
        for (int c = 0; c < 30; c++) {
            double scale = Math.pow(10, random.nextDouble(-3, 5));
            double offset = c % 4 == 3 ? 1e6 : 0;
            Point3D eye = new Point3D(offset, offset + scale, offset + 8 * scale);
            Point3D at = new Point3D(offset + random.nextDouble(-1, 1) * scale, offset, offset);
            Camera camera = switch (c % 3) {
                case 0 -> new Pinhole(eye, at, Vector3D.UP, random.nextDouble(20, 120));
                case 1 -> new ThinLens(eye, at, Vector3D.UP, random.nextDouble(20, 120), 0.2 * scale, 8 * scale);
                default -> new Orthographic(eye, at, Vector3D.UP, random.nextDouble(2, 12) * scale);
            };
            if (c >= 24) {
                // a telephoto 1e8 scene sizes away in a general direction: the tiles' faces are
                // computed from the far eye, where n . eye may cancel
                double far = 1e8 * scale;
                eye = new Point3D(at.x() + 0.48 * far, at.y() + 0.6 * far, at.z() + 0.64 * far);
                camera = new Pinhole(eye, at, Vector3D.UP, Math.toDegrees(2 * Math.atan(8 / 1e8)));
            }
            long[] counts = checkEveryTile(scene(vp, camera, offset, scale, random), tiles, random, "camera " + c);
            listed += counts[0];
            all += counts[1];
            hits += counts[2];
        }
        assertTrue(hits > 2_000, "too few hits on spheres and boxes to tell: " + hits);
        assertTrue(listed < all / 3, "the tiles' lists held " + listed + " of " + all + " objects");
    }

    /**
     * Thin lenses whose aperture is wide against the focal distance (lens radius R 0.5 and 1 times
     * the focal distance f): a lens ray strays from the pinhole's frustum of its tile by up to
     * R |1 - z / f| at depth z, across several tiles here, so a tile's volume without the
     * aperture's spread (the slope R / f, or the offset R of the rays' origins, which matters
     * nearer than f / 2: f is 4 to 24 times the scene scale, the objects 5 to 14 away) leaves out objects its
     * rays hit. The objects are spread three times wider than in the first test, so that the
     * tiles' wide volumes still leave some out. (The first test's lenses, R / f = 0.025, stray
     * less than the objects' margins.)
     */
    @Test
    void aWideApertureFindsEveryHitAmongTheTilesObjects() {
        SplittableRandom random = new SplittableRandom(22);
        ViewPlane vp = new ViewPlane(150, 100, 1, Samplers.byName("regular"), 0, 1);
        List<int[]> tiles = TileOrder.tiles(150, 100);
        long listed = 0;
        long all = 0;
        long hits = 0;
        for (int c = 0; c < 12; c++) {
            double scale = Math.pow(10, random.nextDouble(-3, 5));
            double offset = c % 4 == 3 ? 1e6 : 0;
            Point3D eye = new Point3D(offset, offset + scale, offset + 8 * scale);
            Point3D at = new Point3D(offset + random.nextDouble(-1, 1) * scale, offset, offset);
            double focal = random.nextDouble(4, 24) * scale;
            double radius = (c % 2 == 0 ? 0.5 : 1) * focal;
            Camera camera = new ThinLens(eye, at, Vector3D.UP, random.nextDouble(20, 90), radius, focal);
            long[] counts = checkEveryTile(scene(vp, camera, offset, scale, 3, random), tiles, random, "camera " + c);
            listed += counts[0];
            all += counts[1];
            hits += counts[2];
        }
        assertTrue(hits > 1_000, "too few hits on spheres and boxes to tell: " + hits);
        assertTrue(listed < all * 0.7, "the tiles' lists held " + listed + " of " + all + " objects: nothing to get wrong");
    }

    /**
     * A floor plane below 40 small spheres and boxes scattered over the view, in a world prepared
     * to search by tile.
     */
    private static World scene(ViewPlane vp, Camera camera, double offset, double scale, SplittableRandom random) {
        return scene(vp, camera, offset, scale, 3, random);
    }

    /** As above, the objects spread {@code wide} times as far sideways. */
    private static World scene(ViewPlane vp, Camera camera, double offset, double scale, double wide, SplittableRandom random) {
        World world = new World(vp, camera, new Ambient(0, RGBColor.BLACK));
        world.addObject(new Plane(new Point3D(offset, offset - 3 * scale, offset), new Normal(0, 1, 0)));
        for (int k = 0; k < 40; k++) {
            double x = offset + random.nextDouble(-8, 8) * wide * scale;
            double y = offset + random.nextDouble(-3, 4 * wide) * scale;
            double z = offset + random.nextDouble(-6, 3) * scale;
            double r = random.nextDouble(0.05, 0.5) * wide * scale;
            world.addObject(k % 2 == 0 ? new Sphere(new Point3D(x, y, z), r)
                                       : new Box(new Point3D(x - r, y - r, z - r), new Point3D(x + r, y + r, z + r)));
        }
        world.prepare();
        world.searchByTile();
        return world;
    }

    /**
     * Checks 100 camera rays of every tile (its corners, then random points, from random points of
     * the lens, the first 8 from its rim) against the tile's list: the same closest hit as among
     * all objects. Returns the objects the lists held, the objects all tiles would have tested,
     * and the hits on bounded objects.
     */
    private static long[] checkEveryTile(World world, List<int[]> tiles, SplittableRandom random, String label) {
        Camera camera = world.camera();
        ViewPlane vp = world.viewPlane();
        GeometricObject[][] perTile = TileObjects.of(world, tiles);
        WorkerScratch scratch = new WorkerScratch(world);
        ShadeRec sr = scratch.shadeRec(0);
        Ray ray = new Ray();
        long listed = 0;
        long all = 0;
        long hits = 0;
        for (int i = 0; i < tiles.size(); i++) {
            int[] tile = tiles.get(i);
            GeometricObject[] seen = perTile[i];
            listed += seen == null ? world.searched().size() : seen.length;
            all += world.searched().size();
            for (int k = 0; k < 100; k++) {
                double px = k < 4 ? tile[k % 2 == 0 ? 0 : 2] : random.nextDouble(tile[0], tile[2]);
                double py = k < 4 ? tile[k / 2 == 0 ? 1 : 3] : random.nextDouble(tile[1], tile[3]);
                double angle = random.nextDouble(2 * Math.PI);
                double lens = k < 8 ? 1 : Math.sqrt(random.nextDouble());
                camera.generateRay(vp, px, py, lens * Math.cos(angle), lens * Math.sin(angle), ray);
                scratch.cameraRayObjects = null;
                sr.depth = 0;
                boolean hitAll = world.hit(ray, sr);
                GeometricObject objectAll = sr.object;
                double tAll = sr.t;
                scratch.cameraRayObjects = seen;
                sr.depth = 0;
                boolean hitTile = world.hit(ray, sr);
                String where = label + ", tile " + i + ", ray " + k;
                assertEquals(hitAll, hitTile, where);
                if (hitAll) {
                    hits += objectAll instanceof Plane ? 0 : 1;
                    assertSame(objectAll, sr.object, where);
                    assertEquals(tAll, sr.t, where);
                }
            }
        }
        return new long[] {listed, all, hits};
    }

    @Test
    void noListsUnlessTheWorldSearchesByTile() {
        ViewPlane vp = new ViewPlane(64, 64, 1, Samplers.byName("regular"), 0, 1);
        World world = new World(vp, new Pinhole(new Point3D(0, 0, 5), new Point3D(0, 0, 0), Vector3D.UP, 40),
                                new Ambient(0, RGBColor.BLACK));
        world.addObject(new Sphere(new Point3D(0.9, 0.9, 0), 0.1));
        world.addObject(new Sphere(new Point3D(-0.9, -0.9, 0), 0.1));
        world.prepare();
        assertNull(TileObjects.of(world, TileOrder.tiles(64, 64)));
        world.searchByTile();
        GeometricObject[][] perTile = TileObjects.of(world, TileOrder.tiles(64, 64));
        assertEquals(4, perTile.length);
        int listed = 0;
        for (GeometricObject[] seen : perTile) {
            assertTrue(seen != null && seen.length <= 1, "each sphere is in one quadrant only");
            listed += seen.length;
        }
        assertEquals(2, listed);
    }
}
