package raytracer.study;

import java.util.Arrays;
import raytracer.core.GeometricObject;
import raytracer.core.RayTreeSettings;
import raytracer.core.Tracer;
import raytracer.core.World;
import raytracer.math.RGBColor;
import raytracer.tracers.RayCast;

/**
 * A prepared scene of the renderer in the textbook's terms: its materials and lights as the
 * study's values, under the study's ImmutableWhitted tracer. What the immutable path does not have is
 * refused with one message naming it, never rendered differently.
 */
final class Translation {
    private static final String HAS = "it has matte, phong and reflective materials without textures, Schlick's "
        + "Fresnel or reflection maps, point and directional lights, ambient light, the whitted and ray-cast tracers, "
        + "every term and no cutoff";

    private Translation() {
    }

    /** The textbook tracer for {@code world}, which must be prepared; the materials of objects inside instances and meshes are translated when first hit. */
    static ImmutableWhitted whitted(World world, RayTreeSettings rayTree) {
        if (!rayTree.equals(RayTreeSettings.FULL_TREE)) {
            throw refuse("pass '" + rayTree.pass().key() + "' with cutoff " + rayTree.cutoff());
        }
        Tracer tracer = world.tracer();
        int maxDepth = world.viewPlane().maxDepth();
        int shadedDepth;
        if (tracer instanceof raytracer.tracers.Whitted) {
            shadedDepth = maxDepth;
        } else if (tracer instanceof RayCast) {
            shadedDepth = 0;
        } else {
            throw refuse("tracer " + name(tracer));
        }
        raytracer.core.Light[] sources = world.lights();
        ImmutableLight[] lights = new ImmutableLight[sources.length];
        for (int i = 0; i < sources.length; i++) {
            lights[i] = light(sources[i]);
        }
        if (!(world.ambient() instanceof raytracer.lights.Ambient ambient)) {
            throw refuse("ambient light " + name(world.ambient()));
        }
        Materials materials = new Materials();
        for (GeometricObject object : world.objects()) {
            if (object.getMaterial() != null) {
                materials.of(object.getMaterial());
            }
        }
        return new ImmutableWhitted(world, maxDepth, shadedDepth, lights, ambient.radiance(), materials);
    }

    private static ImmutableLight light(raytracer.core.Light light) {
        if (light instanceof raytracer.lights.PointLight p) {
            return new ImmutablePointLight(p.position(), p.intensity(), p.castsShadows());
        }
        if (light instanceof raytracer.lights.Directional d) {
            return new ImmutableDirectional(d.towardLight(), d.radiance(), d.castsShadows());
        }
        throw refuse("light " + name(light));
    }

    static ImmutableMaterial material(raytracer.core.Material material) {
        if (material instanceof raytracer.materials.Matte m) {
            return phong(m.ka(), m.kd(), m.cd(), null);
        }
        if (material instanceof raytracer.materials.Reflective r) {
            if (r.schlick()) {
                throw refuse("reflective material with Schlick's Fresnel");
            }
            if (r.reflectionMap() != null) {
                throw refuse("reflective material with a reflection map");
            }
            return new ImmutableReflective(phong(r.ka(), r.kd(), r.cd(), lobe(r.specular())), r.mirror().reflectance());
        }
        // Phong itself, not the materials that extend it (as in the book) with rays of their own
        if (material != null && material.getClass() == raytracer.materials.Phong.class) {
            raytracer.materials.Phong p = (raytracer.materials.Phong) material;
            return phong(p.ka(), p.kd(), p.cd(), lobe(p.specular()));
        }
        throw refuse("material " + name(material));
    }

    private static ImmutablePhong phong(double ka, double kd, RGBColor cd, ImmutableGlossySpecular specular) {
        if (cd == null) {
            throw refuse("textured material");
        }
        return new ImmutablePhong(new ImmutableLambertian(ka, cd), new ImmutableLambertian(kd, cd), specular);
    }

    private static ImmutableGlossySpecular lobe(raytracer.brdf.GlossySpecular lobe) {
        return new ImmutableGlossySpecular(lobe.cs(), lobe.scale(), lobe.exp());
    }

    private static String name(Object o) {
        return o == null ? "null" : o.getClass().getSimpleName();
    }

    private static IllegalArgumentException refuse(String what) {
        return new IllegalArgumentException("the allocation study's immutable path has no " + what + "; " + HAS);
    }

    /**
     * The study's counterpart of each material of the renderer, translated when first met (those of
     * objects inside instances and meshes are out of reach before). A scene has few materials, so a
     * list searched by identity costs a few compares per hit; the list is replaced, never changed,
     * so workers read it without a lock.
     */
    static final class Materials {
        private record Entry(raytracer.core.Material from, ImmutableMaterial to) {
        }

        private volatile Entry[] entries = new Entry[0];

        ImmutableMaterial of(raytracer.core.Material material) {
            for (Entry e : entries) {
                if (e.from() == material) {
                    return e.to();
                }
            }
            return add(material);
        }

        private synchronized ImmutableMaterial add(raytracer.core.Material material) {
            for (Entry e : entries) {
                if (e.from() == material) {
                    return e.to();
                }
            }
            Entry added = new Entry(material, material(material));
            Entry[] more = Arrays.copyOf(entries, entries.length + 1);
            more[more.length - 1] = added;
            entries = more;
            return added.to();
        }
    }
}
