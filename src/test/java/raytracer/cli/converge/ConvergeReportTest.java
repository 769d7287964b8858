package raytracer.cli.converge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import raytracer.core.World;
import raytracer.image.ErrorMetrics;
import raytracer.image.chart.Series;
import raytracer.io.scene.SceneLoader;

/** The table, the CSV, the slopes and the chart's curves from a few rows made up for the purpose. */
class ConvergeReportTest {

    private static ConvergeRow row(String config, int spp, double seconds, double relativeRmse) {
        return new ConvergeRow(config, spp, "1", seconds, new ErrorMetrics(relativeRmse * 0.5, relativeRmse, 0.01, 0.25, 3, 7, 0.5));
    }

    /** error = 0.2 t^-0.5 for "a" and 0.1 t^-1 for "b" */
    private static List<ConvergeRow> rows() {
        return List.of(row("a", 1, 0.1, 0.2 / Math.sqrt(0.1)), row("a", 4, 0.4, 0.2 / Math.sqrt(0.4)), row("a", 16, 1.6, 0.2 / Math.sqrt(1.6)),
                       row("b", 1, 0.2, 0.1 / 0.2), row("b", 4, 0.8, 0.1 / 0.8));
    }

    @Test
    void theNoteOnTheReferencesNoise() {
        assertEquals(", its own noise unknown", ConvergeReport.noiseNote(Double.NaN, 0.5));
        assertEquals("", ConvergeReport.noiseNote(0, 0.5));
        assertEquals(", its own noise RMSE 0.01000 (relative 0.02000): errors near it are mostly the reference's",
                     ConvergeReport.noiseNote(0.01, 0.5));
        assertEquals(", its own noise RMSE 0.01000: errors near it are mostly the reference's", ConvergeReport.noiseNote(0.01, 0));
    }

    @Test
    void lightSamplesAreCountedAsTheRendererTakesThem() throws Exception {
        String scene = """
            image: {sampler: SAMPLER}
            lights:
              - {type: rectangle, corner: [0, 2, 0], edge-a: [1, 0, 0], edge-b: [0, 0, 1], samples: 2}
              - {type: disk, center: [0, 2, 0], normal: [0, -1, 0], samples: 16}
              - {type: point, position: [0, 2, 0]}
            objects:
              - {type: plane, normal: [0, 1, 0]}
            """;
        World jittered = SceneLoader.load("s", scene.replace("SAMPLER", "multi-jittered")).world();
        jittered.prepare();
        assertEquals("4-16", ConvergeReport.lightSamples(jittered), "a square pattern takes 4 samples for 2");
        World random = SceneLoader.load("s", scene.replace("SAMPLER", "random")).world();
        random.prepare();
        assertEquals("2-16", ConvergeReport.lightSamples(random));
        World points = SceneLoader.load("s", "lights: [{type: point, position: [0, 2, 0]}]\nobjects: [{type: plane, normal: [0, 1, 0]}]").world();
        points.prepare();
        assertEquals("-", ConvergeReport.lightSamples(points));
    }

    @Test
    void slopesOfExactPowerLaws() {
        Map<String, FittedSlope> slopes = ConvergeReport.slopes(rows());
        assertEquals(-0.5, slopes.get("a").slope(), 1e-12);
        assertEquals(0, slopes.get("a").standardError(), 1e-12, "three points on a line: no scatter");
        assertEquals("-0.50 +/- 0.00 (standard error, 3 points; below five points the error itself is rough)",
                     slopes.get("a").describe());
        assertEquals(-1, slopes.get("b").slope(), 1e-12);
        assertEquals("not fitted: 2 points leave nothing to judge a slope by (give five or more sample counts)",
                     slopes.get("b").describe(), "two points fit any line");
        // one point has no slope
        assertTrue(ConvergeReport.slopes(List.of(row("c", 1, 1, 1))).isEmpty());
    }

    @Test
    void theSlopesStandardErrorIsTheTextbooks() {
        // log10 x = 0, 1, 2, 3, 4 and log10 y = 0, -0.6, -0.9, -1.6, -2.0: slope -0.5, residuals
        // 0.02, -0.08, 0.12, -0.08, 0.02 (sum of squares 0.028), s^2 = 0.028 / 3, Sxx = 10, se = 0.0306
        double[] x = {1, 10, 100, 1000, 10000};
        double[] y = {1, Math.pow(10, -0.6), Math.pow(10, -0.9), Math.pow(10, -1.6), Math.pow(10, -2.0)};
        FittedSlope fit = FittedSlope.of(x, y);
        assertEquals(-0.5, fit.slope(), 1e-12);
        assertEquals(Math.sqrt(0.028 / 3 / 10), fit.standardError(), 1e-12);
        assertEquals("-0.50 +/- 0.03 (standard error, 5 points)", fit.describe());
    }

    @Test
    void theTableAlignsItsColumnsAndNamesTheWorstPixel() {
        String[] lines = ConvergeReport.table(rows()).split("\n");
        assertEquals(6, lines.length);
        assertTrue(lines[0].startsWith("configuration  spp  light samples  seconds"), lines[0]);
        assertTrue(lines[1].startsWith("a                1              1    0.100"), lines[1]);
        assertTrue(lines[1].endsWith("0.2500 at (3, 7)"), lines[1]);
        for (String line : lines) {
            assertEquals(lines[0].length(), line.length(), "every line as wide as the header: '" + line + "'");
        }
        String black = ConvergeReport.table(List.of(new ConvergeRow("d", 1, "-", 1, new ErrorMetrics(0.5, Double.NaN, 1, 1, 0, 0, 0))));
        assertTrue(black.split("\n")[1].contains("  -  "), "no relative RMSE against a black reference: " + black);
    }

    @Test
    void csvQuotesTheNameAndKeepsFullPrecision() {
        String[] lines = ConvergeReport.csv(List.of(row("x, \"y\"", 16, 1.25, 0.1))).split("\n");
        assertEquals("\"x, \"\"y\"\"\",16,1,1.25,0.05,0.1,0.01,0.25,3,7,0.5", lines[1]);
    }

    @Test
    void theChartHasACurvePerConfigurationAndGuides() {
        List<Series> series = ConvergeReport.chart("t", rows(), Double.NaN).series();
        assertEquals(3, series.size());
        assertEquals("a", series.get(0).name());
        assertEquals(3, series.get(0).x().length);
        assertEquals(List.of("1 spp", "4 spp", "16 spp"), series.get(0).labels(), "each point labelled with its samples per pixel");
        Series guide = series.get(2);
        assertTrue(guide.guide());
        // through the first point of "a", spanning all times, falling as t^-1/2
        assertEquals(0.1, guide.x()[0], 0);
        assertEquals(1.6, guide.x()[1], 0);
        assertEquals(0.2 / Math.sqrt(0.1), guide.y()[0], 1e-12);
        assertEquals(0.2 / Math.sqrt(1.6), guide.y()[1], 1e-12);
        // the reference's own noise, an RMSE of 0.01 against a mean of 0.5, is a level line at 0.02
        List<Series> withNoise = ConvergeReport.chart("t", rows(), 0.01).series();
        assertEquals(4, withNoise.size());
        assertTrue(withNoise.get(3).guide());
        assertEquals(0.02, withNoise.get(3).y()[0], 1e-15);
        assertEquals(0.02, withNoise.get(3).y()[1], 1e-15);
        assertEquals(3, ConvergeReport.chart("t", rows(), 0).series().size(), "an exact reference has no noise to show");
    }
}
