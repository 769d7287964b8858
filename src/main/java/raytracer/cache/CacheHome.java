package raytracer.cache;

import java.nio.file.Path;
import java.util.Map;

/**
 * Where this program's caches live by default: {@code $XDG_CACHE_HOME/raytracer/<name>}, or
 * {@code ~/.cache/raytracer/<name>} when that is unset or relative (the XDG Base Directory
 * specification ignores relative paths).
 */
final class CacheHome {
    private CacheHome() {
    }

    /** The default folder of the cache {@code name}, from {@code environment} and the user's {@code home}. */
    static Path folder(Map<String, String> environment, String home, String name) {
        String xdg = environment.get("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute() ? Path.of(xdg) : Path.of(home, ".cache");
        return base.resolve("raytracer").resolve(name);
    }
}
