package raytracer.render;

/** Tiles rendered apart ({@link Renderer#renderTiles}): each one's pixels or sums, in the order asked for, and what they cost. */
public record RenderedTiles(TilePixels[] tiles, RenderStats stats) {
}
