package raytracer.render;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import raytracer.core.PixelFilter;
import raytracer.core.WorkerScratch;
import raytracer.core.World;
import raytracer.filters.Filters;
import raytracer.image.Film;
import raytracer.io.scene.LoadedScene;
import raytracer.io.scene.SceneLoader;

/**
 * What the Gaussian filter costs per pixel against the box, on one thread: one pixel (16 samples
 * of the area-light scene) per operation, the pixels taken tile by tile as the renderer takes them,
 * each tile's samples splatted into its own sums under the Gaussian. The ratio of the two scores is
 * the filter's price on this light four-object scene, where a sample is cheap and the splat weighs
 * the most. Run from the project folder: {@code gradle jmh -Pjmh='FilterBenchmark'}.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class FilterBenchmark {
    @Param({"box", "gaussian"})
    public String filter;

    private Workers workers;
    private Renderer renderer;
    private WorkerScratch scratch;
    private Film film;
    private List<int[]> tiles;
    private PixelSink[] sums;
    private int tile;
    private int x;
    private int y;

    @Setup
    public void setUp() throws Exception {
        LoadedScene loaded = SceneLoader.load(Path.of("scenes", "arealight-spheres.yaml"));
        World world = loaded.world();
        PixelFilter pixelFilter = Filters.byName(filter);
        world.setViewPlane(world.viewPlane().withFilter(pixelFilter));
        world.prepare();
        workers = new Workers(1); // renderPixel runs on the benchmark's thread; the pool stays idle
        renderer = new Renderer(world, loaded.rayTree(), workers, 1);
        scratch = new WorkerScratch(world, loaded.rayTree());
        film = new Film(world.viewPlane().hres(), world.viewPlane().vres());
        tiles = TileOrder.tiles(world.viewPlane().hres(), world.viewPlane().vres());
        sums = new PixelSink[tiles.size()];
        for (int i = 0; i < tiles.size(); i++) {
            int[] t = tiles.get(i);
            sums[i] = pixelFilter.isBox() ? new BoxAverage(film) : new FilteredTile(pixelFilter, t[0], t[1], t[2], t[3]);
        }
        x = tiles.get(0)[0];
        y = tiles.get(0)[1];
    }

    @TearDown
    public void tearDown() {
        workers.close();
    }

    @Benchmark
    public void pixel() {
        renderer.renderPixel(x, y, scratch, sums[tile]);
        // the next pixel of this tile, row by row, then the next tile of the renderer's order
        int[] t = tiles.get(tile);
        if (++x == t[2]) {
            x = t[0];
            if (++y == t[3]) {
                tile = (tile + 1) % tiles.size();
                x = tiles.get(tile)[0];
                y = tiles.get(tile)[1];
            }
        }
    }
}
