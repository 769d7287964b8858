package raytracer.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;
import raytracer.image.AtomicFile;
import raytracer.image.Film;
import raytracer.image.ImageWriters;

/**
 * Where the convergence benchmark keeps the references it renders itself, so the next run reuses
 * them: {@code <scene name>-<key>.pfm} (the linear image times the scene's exposure, as
 * {@code render -o x.pfm} writes it) and a {@code .txt} beside it saying what it is. The key is a
 * SHA-256 of the scene file's bytes and every setting of the reference render; files the scene
 * reads (meshes, maps) and the renderer's own code are not in it, so delete the file after changing
 * those.
 */
final class ReferenceCache {
    private final Path dir;

    ReferenceCache(Path dir) {
        this.dir = dir;
    }

    /** $XDG_CACHE_HOME/raytracer/references, or ~/.cache/raytracer/references. */
    static Path defaultDir(Map<String, String> environment, String home) {
        String xdg = environment.get("XDG_CACHE_HOME");
        Path base = xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute() ? Path.of(xdg) : Path.of(home, ".cache");
        return base.resolve("raytracer").resolve("references");
    }

    /**
     * The file for a reference of {@code sceneName} (for people to recognise it), rendered from
     * {@code sceneBytes} with {@code settings} (one line each, in a fixed order).
     */
    Path file(String sceneName, byte[] sceneBytes, String settings) {
        return dir.resolve(stem(sceneName) + "-" + key(sceneBytes, settings).substring(0, 16) + ".pfm");
    }

    static String key(byte[] sceneBytes, String settings) {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            sha.update(sha.digest(sceneBytes));
            sha.update(settings.getBytes(StandardCharsets.UTF_8));
            return HexFormat.of().formatHex(sha.digest());
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this Java", e);
        }
    }

    private static String stem(String name) {
        int dot = name.lastIndexOf('.');
        return (dot > 0 ? name.substring(0, dot) : name).replaceAll("[^A-Za-z0-9._-]", "_");
    }

    /** The cached reference, if there is one (a damaged file counts as none and is rendered again). */
    Optional<Film> load(Path file) {
        if (!Files.isRegularFile(file)) {
            return Optional.empty();
        }
        try {
            return Optional.of(ImageWriters.readPfm(file));
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    /**
     * Stores a reference (in .pfm units already) and its description, creating the folder if
     * needed; the description goes first, so a reference is never found without it.
     */
    void store(Path file, Film film, String description) throws IOException {
        Files.createDirectories(dir);
        AtomicFile.replace(description(file), out -> out.write(description.getBytes(StandardCharsets.UTF_8)));
        ImageWriters.storePfm(film, 1, file);
    }

    /** The RMSE of the reference's own noise, from the {@value #NOISE_KEY} line of its description. */
    OptionalDouble noise(Path file) {
        try {
            for (String line : Files.readAllLines(description(file), StandardCharsets.UTF_8)) {
                if (line.startsWith(NOISE_KEY)) {
                    double v = Double.parseDouble(line.substring(NOISE_KEY.length()));
                    return v >= 0 && Double.isFinite(v) ? OptionalDouble.of(v) : OptionalDouble.empty();
                }
            }
        } catch (IOException | NumberFormatException e) {
            return OptionalDouble.empty();
        }
        return OptionalDouble.empty();
    }

    static final String NOISE_KEY = "noise-rmse=";

    private static Path description(Path file) {
        return file.resolveSibling(file.getFileName().toString().replaceFirst("\\.pfm$", ".txt"));
    }
}
