package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import raytracer.accel.MedianSplitBuilder;
import raytracer.accel.MeshBVH;
import raytracer.cameras.Orthographic;
import raytracer.core.GeometricObject;
import raytracer.core.Light;
import raytracer.core.Material;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.lights.Ambient;
import raytracer.lights.AreaLight;
import raytracer.lights.PointLight;
import raytracer.materials.Matte;
import raytracer.math.Matrix4;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.samplers.MultiJittered;
import raytracer.shapes.Box;
import raytracer.shapes.Cylinder;
import raytracer.shapes.Disk;
import raytracer.shapes.Instance;
import raytracer.shapes.Plane;
import raytracer.shapes.Rectangle;
import raytracer.shapes.Sphere;
import raytracer.shapes.Triangle;
import raytracer.shapes.mesh.Mesh;
import raytracer.tracers.AreaLighting;

/**
 * A light lying in a surface lights the floor as if the surface were not there (the
 * lamp of a Cornell box modelled flush with its ceiling: the floor had 2% of its light). A floor
 * at y = 0 seen from above by an orthographic camera at max depth 0, a light at y = 2 (a
 * rectangle, the same turned about y, a disk, a point, a sphere whose lowest point is at y = 2,
 * and a rectangle in a tilted ceiling), and a surface through the light's points, each shape in
 * turn; every scene at scales 1e-4 to 1e6 and moved 1e4 and 1e6 from the origin. The floor must be
 * the same to the bit as without the surface: every shadow ray reaches the light. The same surface
 * a thousandth of the height lower must darken the floor, so the scene would show a blocked light.
 */
class FlushLightTest {
    private static final int SIZE = 12;

    static Stream<Arguments> cases() {
        String[][] pairs = {
            {"rectangle", "plane"}, {"rectangle", "rectangle"}, {"rectangle", "disk"}, {"rectangle", "triangle"},
            {"rectangle", "mesh"}, {"rectangle", "box"}, {"rectangle", "cylinder"}, {"rectangle", "instanced box"},
            {"turned rectangle", "plane"}, {"turned rectangle", "mesh"}, {"turned rectangle", "instanced box"},
            {"disk", "plane"}, {"disk", "mesh"}, {"disk", "box"},
            {"point", "plane"}, {"point", "rectangle"}, {"point", "disk"}, {"point", "triangle"}, {"point", "mesh"},
            {"point", "box"}, {"point", "cylinder"}, {"point", "instanced box"},
            {"sphere", "sphere"},
            {"tilted rectangle", "tilted plane"}, {"tilted rectangle", "tilted mesh"}};
        double[][] transforms = {{1e-4, 0}, {1e-2, 0}, {1, 0}, {1e3, 0}, {1e6, 0}, {1, 1e4}, {1, 1e6}};
        return Stream.of(pairs).flatMap(p -> Stream.of(transforms).map(t -> Arguments.of(p[0], p[1], t[0], t[1])));
    }

    @ParameterizedTest(name = "{0} light in a {1} at scale {2}, offset {3}")
    @MethodSource("cases")
    void aSurfaceThroughTheLightLeavesTheFloorAsItWas(String light, String surface, double s, double d) {
        Film open = render(world(light, null, s, d));
        Film flush = render(world(light, surface(surface, light, s, d, 0), s, d));
        Film lower = render(world(light, surface(surface, light, s, d, 1e-3), s, d));
        double lit = mean(open);
        assertTrue(lit > 0, "the floor is dark without the surface");
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                for (int c = 0; c < 3; c++) {
                    int px = x;
                    int py = y;
                    assertEquals(Float.floatToIntBits(open.get(x, y, c)), Float.floatToIntBits(flush.get(x, y, c)),
                                 () -> "pixel " + px + "," + py + ": " + flush.get(px, py, 0) + " with the surface, "
                                       + open.get(px, py, 0) + " without (floor mean " + mean(flush) + " against " + lit + ")");
                }
            }
        }
        assertTrue(mean(lower) < 0.5 * lit, "a surface below the light did not shadow the floor: " + mean(lower) + " of " + lit);
    }

    private static Film render(World world) {
        world.prepare();
        Film film = new Film(SIZE, SIZE);
        Renders.render(world, 2, 3, film);
        return film;
    }

    private static double mean(Film film) {
        double sum = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                sum += film.get(x, y, 0);
            }
        }
        return sum / (SIZE * SIZE);
    }

    /** The point d + s (x, y, z). */
    private static Point3D p(double s, double d, double x, double y, double z) {
        return new Point3D(d + s * x, d + s * y, d + s * z);
    }

    private static World world(String light, GeometricObject surface, double s, double d) {
        World world = new World(new ViewPlane(SIZE, SIZE, 4, new MultiJittered(), 0, 1),
                                new Orthographic(p(s, d, 0, 1.5, 0), p(s, d, 0, 0, 0), new Vector3D(0, 0, -1), 3 * s),
                                new Ambient(0, RGBColor.WHITE));
        world.setTracer(AreaLighting::new);
        Matte matte = new Matte(0, 0.8, RGBColor.WHITE);
        Plane floor = new Plane(p(s, d, 0, 0, 0), new Normal(0, 1, 0));
        floor.setMaterial(matte);
        world.addObject(floor);
        if (surface != null) {
            surface.setMaterial(matte);
            world.addObject(surface);
        }
        world.addLight(light(light, s, d));
        return world;
    }

    /** The tilted ceiling's normal (downwards) and two unit edges in its plane. */
    private static final Vector3D TILTED = new Vector3D(0.2, -1, 0.1).normalize();
    private static final Vector3D TILTED_A = TILTED.cross(new Vector3D(0, 0, 1)).normalize();
    private static final Vector3D TILTED_B = TILTED_A.cross(TILTED);

    /**
     * Rectangles sample by solid angle whatever lies near them: otherwise the surface through the
     * light would itself make the light choose it ({@link AreaLight#sampleBySolidAngle}), and the
     * two images would differ by their noise, not by a leak.
     */
    private static Light light(String light, double s, double d) {
        Light made = madeLight(light, s, d);
        if (made instanceof AreaLight area && light.endsWith("rectangle")) {
            area.sampleBySolidAngle(true);
        }
        return made;
    }

    private static Light madeLight(String light, double s, double d) {
        double turn = Math.toRadians(30);
        return switch (light) {
            case "rectangle" -> AreaLight.rectangle(p(s, d, -0.5, 2, -0.5), new Vector3D(s, 0, 0), new Vector3D(0, 0, s), 5,
                                                    RGBColor.WHITE, 16);
            case "turned rectangle" -> AreaLight.rectangle(p(s, d, -0.5, 2, -0.3),
                                                           new Vector3D(Math.cos(turn) * s, 0, Math.sin(turn) * s),
                                                           new Vector3D(-Math.sin(turn) * s, 0, Math.cos(turn) * s), 5, RGBColor.WHITE, 16);
            case "disk" -> AreaLight.disk(p(s, d, 0, 2, 0), new Vector3D(0, -1, 0), 0.5 * s, 5, RGBColor.WHITE, 16);
            case "point" -> new PointLight(5 * s * s, RGBColor.WHITE, p(s, d, 0.1, 2, 0.2));
            case "sphere" -> AreaLight.sphere(p(s, d, 0, 2.5, 0), 0.5 * s, 5, RGBColor.WHITE, 16);
            // corner and edges in the tilted plane through (0, 2, 0), to rounding; b x a faces down
            case "tilted rectangle" -> AreaLight.rectangle(p(s, d, 0, 2, 0).add(TILTED_A.scale(-0.5 * s)).add(TILTED_B.scale(-0.5 * s)),
                                                           TILTED_B.scale(s), TILTED_A.scale(s), 5, RGBColor.WHITE, 16);
            default -> throw new IllegalArgumentException(light);
        };
    }

    /** The surface through the light's points (at y = 2), or {@code lower} times the height below them. */
    private static GeometricObject surface(String shape, String light, double s, double d, double lower) {
        double y = 2 - 2 * lower;
        Point3D center = p(s, d, 0, y, 0);
        return switch (shape) {
            case "plane" -> new Plane(center, new Normal(0, -1, 0));
            case "rectangle" -> new Rectangle(p(s, d, -3, y, -3), new Vector3D(0, 0, 6 * s), new Vector3D(6 * s, 0, 0));
            case "disk" -> new Disk(center, new Vector3D(0, -1, 0), 3 * s);
            case "triangle" -> new Triangle(p(s, d, -4, y, -4), p(s, d, 4, y, -4), p(s, d, 0, y, 5));
            case "mesh" -> mesh(new Point3D[] {p(s, d, -3, y, -3), p(s, d, 3, y, -3), p(s, d, 3, y, 3), p(s, d, -3, y, 3)});
            case "box" -> new Box(p(s, d, -3, y, -3), p(s, d, 3, y + 1, 3));
            case "cylinder" -> new Instance(new Cylinder(0, s, 3 * s, true), Matrix4.translate(d, d + s * y, d));
            // a cube of half-size 3 s, turned about y, its bottom face at y
            case "instanced box" -> new Instance(new Box(new Point3D(-1, -1, -1), new Point3D(1, 1, 1)),
                                                 Matrix4.translate(d, d + s * (y + 3), d).multiply(Matrix4.rotateY(25))
                                                        .multiply(Matrix4.scale(3 * s, 3 * s, 3 * s)));
            case "sphere" -> new Sphere(p(s, d, 0, 2.5, 0), (0.5 + lower) * s);
            case "tilted plane" -> new Plane(p(s, d, 0, 2, 0).add(TILTED.scale(2 * lower * s)), new Normal(TILTED.x(), TILTED.y(), TILTED.z()));
            case "tilted mesh" -> {
                Point3D c = p(s, d, 0, 2, 0).add(TILTED.scale(2 * lower * s));
                Vector3D a = TILTED_A.scale(3 * s);
                Vector3D b = TILTED_B.scale(3 * s);
                yield mesh(new Point3D[] {c.add(a.scale(-1)).add(b.scale(-1)), c.add(a).add(b.scale(-1)), c.add(a).add(b),
                                          c.add(a.scale(-1)).add(b)});
            }
            default -> throw new IllegalArgumentException(shape + " for " + light);
        };
    }

    /** A quad of two triangles in a BVH, as a loaded OBJ would be. */
    private static GeometricObject mesh(Point3D[] corners) {
        double[] positions = new double[12];
        for (int i = 0; i < 4; i++) {
            positions[3 * i] = corners[i].x();
            positions[3 * i + 1] = corners[i].y();
            positions[3 * i + 2] = corners[i].z();
        }
        Mesh mesh = new Mesh(positions, null, null, new int[] {0, 1, 2, 0, 2, 3}, null);
        return new MeshBVH(mesh, new MedianSplitBuilder(1).build(MeshBVH.triangleBoxes(mesh)), List.<Material>of());
    }
}
