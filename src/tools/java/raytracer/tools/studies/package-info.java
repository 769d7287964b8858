/**
 * The Java programs of the studies under tools/studies/ (tools/README.md): large meshes made from
 * the dragon for the scale study, and the model and charts of the Spark measurements. Built into
 * build/libs/render-tools.jar, against src/main, so that they keep up with the code; in neither the
 * suite nor render.jar.
 */
package raytracer.tools.studies;
