package raytracer.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * A cluster's SnakeYAML must not change how a scene reads. pyspark 4.1.3 ships SnakeYAML 2.5 in
 * its jars, before the application's on the driver's class path; the driver then runs the job in
 * {@link OursFirst}, which finds ours (and our classes) first and everything else, Spark included,
 * where the cluster's loader does. Here the cluster's loader holds SnakeYAML 2.5 (from Maven
 * Central, as pyspark ships it), and a scene file is read through our loader with ours.
 */
class OursFirstTest {
    private static URL location(Class<?> type) {
        return type.getProtectionDomain().getCodeSource().getLocation();
    }

    @Test
    void oursComeFirstAndTheRestFromTheCluster() throws Exception {
        String clusterYaml = System.getProperty("raytracer.test.clusterSnakeyaml");
        assertTrue(clusterYaml != null && clusterYaml.endsWith("snakeyaml-2.5.jar"), "the build names SnakeYAML 2.5: " + clusterYaml);
        URL ourYaml = location(org.yaml.snakeyaml.LoaderOptions.class);
        URL ourClasses = location(raytracer.io.scene.SceneFile.class);
        // the list of registered types, which render.jar holds beside the classes and a build keeps apart
        String services = "META-INF/services/raytracer.core.Registration";
        String found = raytracer.io.scene.SceneFile.class.getClassLoader().getResource(services).toString();
        URL ourResources = new URL(found.substring(0, found.length() - services.length()));
        try (URLClassLoader cluster = new URLClassLoader(new URL[] {Path.of(clusterYaml).toUri().toURL()}, ClassLoader.getPlatformClassLoader());
             OursFirst loader = new OursFirst(new URL[] {ourClasses, ourResources, ourYaml}, cluster)) {
            assertTrue(location(cluster.loadClass("org.yaml.snakeyaml.LoaderOptions")).getPath().endsWith("snakeyaml-2.5.jar"));
            Class<?> yaml = loader.loadClass("org.yaml.snakeyaml.LoaderOptions");
            assertEquals(ourYaml, location(yaml), "ours first");
            assertSame(String.class, loader.loadClass("java.lang.String"));
            // a scene read in that loader uses our SnakeYAML
            Class<?> sceneFile = loader.loadClass("raytracer.io.scene.SceneFile");
            Object read = sceneFile.getMethod("of", String.class, String.class).invoke(null, "s.yaml", "image: {width: 33}\nobjects: []\n");
            Object vp = sceneFile.getMethod("viewPlane").invoke(read);
            assertEquals(33, vp.getClass().getMethod("hres").invoke(vp));
            assertEquals(ourYaml, location(loader.loadClass("org.yaml.snakeyaml.composer.Composer")));
        }
    }
}
