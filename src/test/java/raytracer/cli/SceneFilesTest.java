package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import raytracer.accel.Aggregation;
import raytracer.core.ViewPlane;
import raytracer.core.World;
import raytracer.image.Film;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneException;
import raytracer.io.scene.SceneLoader;
import raytracer.render.RenderStats;
import raytracer.render.Renders;

/**
 * Every scene file in scenes/ (the report's figures, the benches, the default) loads without a
 * warning and renders, 16 x 12 pixels at one sample, to a finite image that is not one flat colour.
 * A file it reads that is missing fails with the scene's name and the asset's path.
 */
class SceneFilesTest {
    private static final Pattern FILE = Pattern.compile("\\bfile:\\s*([^,}\\s]+)");

    static Stream<Path> sceneFiles() throws IOException {
        try (Stream<Path> files = Files.list(Path.of("scenes"))) {
            List<Path> scenes = files.filter(p -> p.toString().endsWith(".yaml")).sorted().toList();
            assertTrue(scenes.size() >= 20, "scenes/ holds the figures, the benches and the default: " + scenes);
            return scenes.stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sceneFiles")
    void loadsAndRendersTiny(Path scene) throws IOException, SceneException {
        List<String> missing = new ArrayList<>();
        Matcher m = FILE.matcher(Files.readString(scene));
        while (m.find()) {
            Path asset = scene.toAbsolutePath().getParent().resolve(m.group(1)).normalize();
            if (!Files.isRegularFile(asset)) {
                missing.add(m.group(1) + " (" + asset + ")");
            }
        }
        assertEquals(List.of(), missing, scene + " reads files that are not there; they belong in assets/");
        LoadedScene loaded = SceneLoader.load(scene);
        assertEquals(List.of(), loaded.report().warnings(), scene + " loads with warnings");
        World world = loaded.world();
        world.setViewPlane(world.viewPlane().withResolution(16, 12).withSamples(1));
        world.prepare(objects -> Aggregation.organize(objects, Aggregation.Mode.AUTO));
        ViewPlane vp = world.viewPlane();
        Film film = new Film(vp.hres(), vp.vres());
        RenderStats stats = Renders.render(world, loaded.rayTree(), 2, 1, film);
        assertEquals(0, stats.nonFiniteSamples(), scene + ": non-finite samples");
        float first = film.get(0, 0, 1);
        boolean varies = false;
        for (int y = 0; y < vp.vres(); y++) {
            for (int x = 0; x < vp.hres(); x++) {
                for (int c = 0; c < 3; c++) {
                    assertTrue(Float.isFinite(film.get(x, y, c)), scene + ": pixel " + x + ", " + y);
                }
                varies |= film.get(x, y, 1) != first;
            }
        }
        assertTrue(varies, scene + " renders one flat colour");
    }
}
