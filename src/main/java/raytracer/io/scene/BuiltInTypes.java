package raytracer.io.scene;

import java.util.Set;
import raytracer.core.Registrar;
import raytracer.core.Registration;

/**
 * The scene file's built-in types, by name, with their own keys (docs/scene-format.md); each is
 * made by its reader. Registered as any other type ({@link Registration}), so the readers have no
 * list of their own: a registered type is read, checked and listed as these are.
 */
public final class BuiltInTypes implements Registration {
    private static final Set<String> AREA_LIGHT = Set.of("radiance", "color", "samples", "visible");
    private static final Set<String> FITTED = Set.of("preset", "rho-d", "rho-s", "ka", "seed-compatible");

    @Override
    public void register(Registrar registrar) {
        registrar.camera("pinhole", Set.of("fov"), CameraReader::pinhole);
        registrar.camera("thin-lens", Set.of("fov", "lens-radius", "focal-distance"), CameraReader::thinLens);
        registrar.camera("orthographic", Set.of("view-height"), CameraReader::orthographic);

        registrar.ambient("constant", Set.of("radiance", "color"), LightReader::constantAmbient);

        registrar.light("point", Set.of("position", "intensity", "color"), LightReader::point);
        registrar.light("directional", Set.of("direction", "radiance", "color"), LightReader::directional);
        registrar.light("rectangle", with(AREA_LIGHT, "corner", "edge-a", "edge-b", "sampling"), SceneFactory.of(LightReader::rectangle));
        registrar.light("disk", with(AREA_LIGHT, "center", "normal", "radius"), SceneFactory.of(LightReader::disk));
        registrar.light("sphere", with(AREA_LIGHT, "center", "radius"), SceneFactory.of(LightReader::sphere));

        registrar.object("sphere", Set.of("center", "radius"), ObjectReader::sphere);
        registrar.object("plane", Set.of("point", "normal"), ObjectReader::plane);
        registrar.object("box", Set.of("min", "max"), ObjectReader::box);
        registrar.object("cylinder", Set.of("bottom", "top", "radius", "closed"), ObjectReader::cylinder);
        registrar.object("triangle", Set.of("vertices"), SceneFactory.of(ObjectReader::triangle));
        registrar.object("mesh", Set.of("file", "smooth", "bvh", "normal-map"), SceneFactory.of(ObjectReader::mesh));

        registrar.material("matte", Set.of("ka", "kd", "color", "texture"), MaterialReader::matte);
        registrar.material("phong", Set.of("ka", "kd", "color", "ks", "specular-color", "exponent", "normalized", "texture"),
                           MaterialReader::phong);
        registrar.material("reflective", Set.of("ka", "kd", "color", "ks", "specular-color", "exponent", "kr", "reflect-color",
                                                "fresnel", "texture", "reflection-map"), MaterialReader::reflective);
        registrar.material("dielectric", Set.of("ior", "absorption", "ks", "exponent", "reflection-map"), MaterialReader::dielectric);
        registrar.material("thin-dielectric", Set.of("ior", "ks", "exponent", "reflection-map"), MaterialReader::thinDielectric);
        registrar.material("glossy", Set.of("ka", "kd", "color", "ks", "specular-color", "exponent", "samples", "normalized",
                                            "texture", "reflection-map"), MaterialReader::glossy);
        registrar.material("ward", with(FITTED, "alpha"), MaterialReader::ward);
        registrar.material("ward-duer", with(FITTED, "alpha"), MaterialReader::wardDuer);
        registrar.material("blinn-phong", with(FITTED, "exponent"), MaterialReader::blinnPhong);

        registrar.texture("checker", Set.of("color-a", "color-b", "size"), TextureReader::checker);
        registrar.texture("constant", Set.of("color"), TextureReader::constant);
        registrar.texture("image", Set.of("file"), SceneFactory.of(TextureReader::imageTexture));
    }

    private static Set<String> with(Set<String> keys, String... more) {
        Set<String> all = new java.util.HashSet<>(keys);
        all.addAll(Set.of(more));
        return all;
    }
}
