package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Locates the test data kept in the repository's {@code assets/} folder (provenance in its
 * SOURCES.md), relative to the working directory, which the build sets to the project folder;
 * {@code -Draytracer.assets=DIR} reads another folder instead. A missing file fails the test that
 * needs it, naming the file: such a test never passes silently.
 */
public final class TestAssets {
    private TestAssets() {
    }

    public static Path path(String relative) {
        String configured = System.getProperty("raytracer.assets");
        Path root = Path.of(configured != null ? configured : "assets");
        Path file = root.resolve(relative);
        if (!Files.isRegularFile(file)) {
            fail("test asset " + file.toAbsolutePath().normalize() + " is missing: tests run from the project folder, "
                 + "which holds assets/ (or pass -Draytracer.assets=DIR); see assets/SOURCES.md");
        }
        return file;
    }
}
