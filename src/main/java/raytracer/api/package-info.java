/**
 * Rendering a scene file, or part of one, from another program: the one place where a scene file
 * and a render's options ({@link raytracer.api.SceneOptions}) become a scene to render
 * ({@link raytracer.api.Scene}), its image settings read without building anything
 * ({@link raytracer.api.ImageSettings}), and each frame loaded and prepared for its view
 * ({@link raytracer.api.SceneFrame}), whose renderer renders the whole image or a list of tiles
 * into arrays ({@link raytracer.render.Renderer#renderTiles}, {@link raytracer.render.TileImage});
 * and where the images go: the frames asked for ({@link raytracer.api.FrameRange}), their files
 * ({@link raytracer.api.FrameFiles}), and whether a file can be written ({@link raytracer.api.OutputFile}).
 * The command line and the Spark job ({@code raytracer.spark}) both go through here, so an option
 * means the same in both.
 */
package raytracer.api;
