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
        List<int[]> tiles = Renderer.tiles(width, height);
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
            World world = new World(vp, camera, new Ambient(0, RGBColor.BLACK));
            world.addObject(new Plane(new Point3D(offset, offset - 3 * scale, offset), new Normal(0, 1, 0)));
            for (int k = 0; k < 40; k++) {
                double x = offset + random.nextDouble(-8, 8) * scale;
                double y = offset + random.nextDouble(-3, 4) * scale;
                double z = offset + random.nextDouble(-6, 3) * scale;
                double r = random.nextDouble(0.05, 0.5) * scale;
                world.addObject(k % 2 == 0 ? new Sphere(new Point3D(x, y, z), r)
                                           : new Box(new Point3D(x - r, y - r, z - r), new Point3D(x + r, y + r, z + r)));
            }
            world.prepare();
            world.searchByTile();
            GeometricObject[][] perTile = TileObjects.of(world, tiles);
            WorkerScratch scratch = new WorkerScratch(world);
            ShadeRec sr = scratch.shadeRec(0);
            Ray ray = new Ray();
            for (int i = 0; i < tiles.size(); i++) {
                int[] tile = tiles.get(i);
                GeometricObject[] seen = perTile[i];
                listed += seen == null ? world.searched().size() : seen.length;
                all += world.searched().size();
                for (int k = 0; k < 100; k++) {
                    // the tile's corners first, then random points, from random points of the lens
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
                    assertEquals(hitAll, hitTile, "camera " + c + ", tile " + i + ", ray " + k);
                    if (hitAll) {
                        hits += objectAll instanceof Plane ? 0 : 1;
                        assertSame(objectAll, sr.object, "camera " + c + ", tile " + i + ", ray " + k);
                        assertEquals(tAll, sr.t, "camera " + c + ", tile " + i + ", ray " + k);
                    }
                }
            }
        }
        assertTrue(hits > 2_000, "too few hits on spheres and boxes to tell: " + hits);
        assertTrue(listed < all / 3, "the tiles' lists held " + listed + " of " + all + " objects");
    }

    @Test
    void noListsUnlessTheWorldSearchesByTile() {
        ViewPlane vp = new ViewPlane(64, 64, 1, Samplers.byName("regular"), 0, 1);
        World world = new World(vp, new Pinhole(new Point3D(0, 0, 5), new Point3D(0, 0, 0), Vector3D.UP, 40),
                                new Ambient(0, RGBColor.BLACK));
        world.addObject(new Sphere(new Point3D(0.9, 0.9, 0), 0.1));
        world.addObject(new Sphere(new Point3D(-0.9, -0.9, 0), 0.1));
        world.prepare();
        assertNull(TileObjects.of(world, Renderer.tiles(64, 64)));
        world.searchByTile();
        GeometricObject[][] perTile = TileObjects.of(world, Renderer.tiles(64, 64));
        assertEquals(4, perTile.length);
        int listed = 0;
        for (GeometricObject[] seen : perTile) {
            assertTrue(seen != null && seen.length <= 1, "each sphere is in one quadrant only");
            listed += seen.length;
        }
        assertEquals(2, listed);
    }
}
