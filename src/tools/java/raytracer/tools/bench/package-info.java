/**
 * The Java programs of the A/B harness, tools/bench/ab (tools/README.md): renders of two jars paired
 * in one JVM, and the noise of two jars' images against a seed's. Built into
 * build/libs/render-tools.jar; in neither the suite nor render.jar.
 */
package raytracer.tools.bench;
