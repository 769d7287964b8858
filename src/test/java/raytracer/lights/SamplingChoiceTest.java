package raytracer.lights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;
import raytracer.cameras.Orthographic;
import raytracer.core.GeometricObject;
import raytracer.core.ShadeRec;
import raytracer.core.ViewPlane;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.math.MutableVec3;
import raytracer.math.Normal;
import raytracer.math.Point3D;
import raytracer.math.RGBColor;
import raytracer.math.Vector3D;
import raytracer.samplers.MultiJittered;
import raytracer.shapes.Plane;
import raytracer.shapes.Rectangle;
import raytracer.shapes.Sphere;

/**
 * A rectangle light chooses, once when the world is prepared, to draw its samples by solid angle
 * (some object lies near it) or by area (everything lies far): the same way at every point, so that
 * no pixel mixes the two maps. The density after a sample tells which: 1 / area by area.
 */
class SamplingChoiceTest {
    /** A 2 x 2 light 4 above the origin, facing down: area 4. */
    private static AreaLight light() {
        return AreaLight.rectangle(new Point3D(-1, 4, -1), new Vector3D(2, 0, 0), new Vector3D(0, 0, 2), 1, RGBColor.WHITE, 1);
    }

    private static World world(AreaLight light, GeometricObject... objects) {
        World world = new World(new ViewPlane(1, 1, 1, new MultiJittered(), 0, 1),
            new Orthographic(new Point3D(0, 10, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1), new Ambient(0, RGBColor.WHITE));
        for (GeometricObject object : objects) {
            world.addObject(object);
        }
        world.addLight(light);
        world.prepare();
        return world;
    }

    /** The density of the sample (0.3, 0.7) of {@code light} from (x, y, z). */
    private static double pdfFrom(World world, AreaLight light, double x, double y, double z) {
        ShadeRec sr = new WorkerScratch(world).shadeRec(0);
        sr.hitPoint.set(x, y, z);
        sr.normal.set(0, 1, 0);
        light.sample(sr, 0.3, 0.7, new MutableVec3());
        return light.pdf(sr);
    }

    @Test
    void aLightFarFromEveryObjectIsSampledByAreaEvenFromANearPoint() {
        // a sphere of radius 0.8 on the floor: at the corners of its box the farthest corner of the
        // light is at most 1.46 times as far as its nearest point
        AreaLight light = light();
        World world = world(light, new Sphere(new Point3D(0, 0.8, 0), 0.8));
        assertEquals(0.25, pdfFrom(world, light, 0, 1.6, 0), 0, "from the sphere's top");
        assertEquals(0.25, pdfFrom(world, light, 0, 3.9, 0), 0, "from a point just below the light, where no object is");
    }

    @Test
    void aLightNearSomeObjectIsSampledBySolidAngleEverywhere() {
        AreaLight light = light();
        // a small sphere 0.3 below the light's edge: its farthest corner there is some 7 times as far as its nearest point
        World world = world(light, new Sphere(new Point3D(0, 0.8, 0), 0.8), new Sphere(new Point3D(1.2, 3.5, 0), 0.1));
        assertNotEquals(0.25, pdfFrom(world, light, 0, 1.6, 0), "from the far sphere's top as well");
        assertNotEquals(0.25, pdfFrom(world, light, 1.2, 3.4, 0));
    }

    @Test
    void aFloorNearTheLightCountsThroughItsPlanesBox() {
        AreaLight near = light();
        // the floor 0.5 below the light: from a point of it beside the light the spread is large
        World world = world(near, new Plane(new Point3D(0, 3.5, 0), new Normal(0, 1, 0)));
        assertNotEquals(0.25, pdfFrom(world, near, 0, 3.5, 0));
        AreaLight far = light();
        // the floor 40 below: nowhere near (an unbounded box along y would have reached the light)
        World farWorld = world(far, new Plane(new Point3D(0, -36, 0), new Normal(0, 1, 0)));
        assertEquals(0.25, pdfFrom(farWorld, far, 0, -36, 0), 0);
    }

    @Test
    void theLightsOwnVisibleSurfaceDoesNotCount() {
        AreaLight light = light();
        World world = world(light, new Rectangle(new Point3D(-1, 4, -1), new Vector3D(2, 0, 0), new Vector3D(0, 0, 2)),
                            new Sphere(new Point3D(0, 0.8, 0), 0.8));
        assertEquals(0.25, pdfFrom(world, light, 0, 1.6, 0), 0);
    }

    @Test
    void aLightNotYetPreparedSamplesBySolidAngle() {
        AreaLight light = light();
        World world = new World(new ViewPlane(1, 1, 1, new MultiJittered(), 0, 1),
            new Orthographic(new Point3D(0, 10, 0), Point3D.ORIGIN, new Vector3D(0, 0, -1), 1), new Ambient(0, RGBColor.WHITE));
        assertNotEquals(0.25, pdfFrom(world, light, 0, 2, 0));
    }
}
