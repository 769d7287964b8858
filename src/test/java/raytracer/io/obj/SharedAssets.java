package raytracer.io.obj;

import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Locates the large test data of ../shared/assets (or -Draytracer.assets=...). When it is missing,
 * tests that need it fail and say so: they never pass silently.
 */
public final class SharedAssets {
    private SharedAssets() {
    }

    public static Path path(String relative) {
        String configured = System.getProperty("raytracer.assets");
        Path root = configured != null ? Path.of(configured) : Path.of("..", "shared", "assets");
        Path file = root.resolve(relative);
        if (!Files.isRegularFile(file)) {
            fail("test asset " + file.toAbsolutePath().normalize() + " is missing: this test needs the shared assets "
                 + "folder (../shared/assets beside the checkout, or -Draytracer.assets=DIR); see its SOURCES.md");
        }
        return file;
    }
}
