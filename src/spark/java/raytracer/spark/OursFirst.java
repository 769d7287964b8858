package raytracer.spark;

import java.net.URL;
import java.net.URLClassLoader;

/**
 * A class loader that finds our classes and the libraries render.jar holds (SnakeYAML, picocli)
 * in our jars first, and everything else (Spark, Hadoop, the JDK) where its parent does. A
 * cluster's own SnakeYAML (pyspark 4.1.3 ships 2.5) must not change how a scene file reads; on the
 * executors the job asks Spark for {@code spark.executor.userClassPathFirst}, and on the driver,
 * whose class path spark-submit has fixed before the job's code runs, {@link SparkRender#main}
 * runs itself again in this loader when the SnakeYAML it sees is not render.jar's.
 */
final class OursFirst extends URLClassLoader {
    private static final String[] OURS = {"raytracer.", "org.yaml.snakeyaml.", "picocli."};

    static {
        registerAsParallelCapable();
    }

    OursFirst(URL[] jars, ClassLoader parent) {
        super("render-spark", jars, parent);
    }

    static boolean ours(String name) {
        for (String prefix : OURS) {
            if (name.startsWith(prefix)) {
                return true;
            }
        }
        return false;
    }

    @Override
    protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
        if (!ours(name)) {
            return super.loadClass(name, resolve);
        }
        synchronized (getClassLoadingLock(name)) {
            Class<?> c = findLoadedClass(name);
            if (c == null) {
                try {
                    c = findClass(name);
                } catch (ClassNotFoundException e) {
                    c = super.loadClass(name, false);
                }
            }
            if (resolve) {
                resolveClass(c);
            }
            return c;
        }
    }

    @Override
    public URL getResource(String name) {
        String asClass = name.replace('/', '.');
        URL own = ours(asClass) ? findResource(name) : null;
        return own != null ? own : super.getResource(name);
    }
}
