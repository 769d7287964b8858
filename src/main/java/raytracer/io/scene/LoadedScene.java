package raytracer.io.scene;

import raytracer.core.RayTreeSettings;
import raytracer.core.World;
import raytracer.image.DisplayEncoding;

/**
 * A scene file as read: the {@link World} (not yet prepared: the caller may still override the
 * view plane), how much of the ray tree the file asks to trace ({@code pass}, {@code image.cutoff}),
 * how its PNG is encoded ({@code image.encoding}) and the report of the loading itself.
 */
public record LoadedScene(World world, RayTreeSettings rayTree, DisplayEncoding encoding, LoadReport report) {
}
