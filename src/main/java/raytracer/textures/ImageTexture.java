package raytracer.textures;

import raytracer.core.ShadeRec;
import raytracer.core.Texture;
import raytracer.image.Film;
import raytracer.math.MutableRgb;

/**
 * An image wrapped over u, v in [0, 1] (v up, as OBJ's vt), repeating outside, with bilinear
 * filtering of the linear texels.
 */
public final class ImageTexture implements Texture {
    private final Film image;

    public ImageTexture(Film image) {
        this.image = image;
    }

    @Override
    public void getColor(ShadeRec sr, MutableRgb out) {
        Bilinear.lookup(image, sr.u, 1 - sr.v, out);
    }
}
