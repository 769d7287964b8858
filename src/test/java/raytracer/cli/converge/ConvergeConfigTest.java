package raytracer.cli.converge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** How --config values become configurations, and what they are called. */
class ConvergeConfigTest {

    @Test
    void alternativesSpellOutEveryCombinationInOrder() {
        List<ConvergeConfig> configs = ConvergeConfig.parse("sampler=random/multi-jittered, light-samples=1/4/16, cutoff=0.001");
        assertEquals(6, configs.size());
        assertEquals(new ConvergeConfig(null, "random", 1, 0.001), configs.get(0));
        assertEquals(new ConvergeConfig(null, "random", 4, 0.001), configs.get(1));
        assertEquals(new ConvergeConfig(null, "multi-jittered", 16, 0.001), configs.get(5));
    }

    @Test
    void unsetKeysKeepTheScenesValue() {
        assertEquals(List.of(new ConvergeConfig(null, null, 4, null)), ConvergeConfig.parse("light-samples=4"));
        assertEquals(List.of(new ConvergeConfig("mine", "jittered", null, null)), ConvergeConfig.parse("label=mine,sampler=jittered"));
    }

    @Test
    void namesSayWhatTheRendererUses() {
        ConvergeConfig c = new ConvergeConfig(null, null, 2, null);
        assertEquals("multi-jittered, 4 light samples", c.name("multi-jittered", "4", 0));
        assertEquals("random, 1 light sample, cutoff 0.001", c.name("random", "1", 0.001));
        assertEquals("mine", new ConvergeConfig("mine", null, null, null).name("random", "1", 0));
    }

    @Test
    void mistakesSayWhatIsExpected() {
        String[][] cases = {
            {"sampler=poisson-disk", "unknown sampler 'poisson-disk'; allowed: regular, random"},
            {"lights=4", "expected key=value pairs joined by commas, with keys cutoff, label, light-samples, sampler; got 'lights=4'"},
            {"light-samples=0", "light-samples must be 1 to 1048576, got 0"},
            {"light-samples=many", "light-samples must be a whole number, got 'many'"},
            {"cutoff=1", "cutoff must be in [0, 1), got 1"},
            {"sampler=random,sampler=jittered", "'sampler' given twice"},
            {"sampler", "got 'sampler'"},
            {"label=", "the label is empty"}};
        for (String[] c : cases) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ConvergeConfig.parse(c[0]), c[0]);
            assertTrue(e.getMessage().startsWith("--config '" + c[0] + "': ") && e.getMessage().contains(c[1]), e.getMessage());
        }
    }
}
