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
import java.util.function.Consumer;
import raytracer.image.AtomicFile;
import raytracer.image.FileKind;
import raytracer.image.Film;
import raytracer.image.IoReason;
import raytracer.image.ImageWriters;

/**
 * Where the convergence benchmark keeps the references it renders itself, so the next run reuses
 * them: {@code <scene name>-<key>.pfm} (the linear image times the scene's exposure, as
 * {@code render -o x.pfm} writes it) and a {@code .txt} beside it saying what it is, with the
 * SHA-256 of the image's bytes: a reference that does not match it is rendered again. The key is a
 * SHA-256 of the scene file's bytes, every setting of the reference render and the content of every
 * file the scene reads (meshes, MTL files, textures: {@link ConvergeReference#inputs}); the
 * renderer's own code is not in it, so delete the folder after changing that.
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

    /**
     * The cached reference, if there is one and it is as stored: its bytes must have the SHA-256
     * its description holds and every pixel must be finite. Anything else counts as none, to be
     * rendered again; {@code why} is told why when a file was there.
     */
    Optional<Film> load(Path file, Consumer<String> why) {
        if (!Files.isRegularFile(file)) {
            return Optional.empty();
        }
        try {
            byte[] bytes = Files.readAllBytes(file);
            String sum = value(file, SHA_KEY);
            if (sum == null || !sum.equals(sha256(bytes))) {
                why.accept("does not match its checksum");
                return Optional.empty();
            }
            Film film = ImageWriters.readPfm(bytes, file);
            for (int y = 0; y < film.height(); y++) {
                for (int x = 0; x < film.width(); x++) {
                    for (int c = 0; c < 3; c++) {
                        if (!Float.isFinite(film.get(x, y, c))) {
                            why.accept("holds a pixel that is not a finite number");
                            return Optional.empty();
                        }
                    }
                }
            }
            return Optional.of(film);
        } catch (IOException e) {
            why.accept("cannot be read (" + IoReason.of(e) + ")");
            return Optional.empty();
        }
    }

    /** The cached reference, if there is one as stored (as {@link #load(Path, Consumer)}, saying nothing). */
    Optional<Film> load(Path file) {
        return load(file, why -> { });
    }

    /**
     * Fails when something other than a folder is where the references are kept: found before a
     * reference is rendered, not after.
     */
    void checkFolder() throws IOException {
        FileKind kind = FileKind.of(dir);
        if (kind != FileKind.DIRECTORY && kind != FileKind.MISSING) {
            throw new IOException("cannot keep references in " + dir + ": it is " + kind.words() + ", not a folder");
        }
    }

    /**
     * Stores a reference (in .pfm units already) and its description with the SHA-256 of the
     * image's bytes, creating the folder if needed; the description goes first, so a reference is
     * never found without it.
     */
    void store(Path file, Film film, String description) throws IOException {
        checkFolder();
        Files.createDirectories(dir);
        byte[] image = ImageWriters.pfmBytes(film, 1);
        String text = description + SHA_KEY + sha256(image) + "\n";
        AtomicFile.replace(description(file), out -> out.write(text.getBytes(StandardCharsets.UTF_8)));
        AtomicFile.replace(file, out -> out.write(image));
    }

    static final String SHA_KEY = "sha-256=";

    private static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this Java", e);
        }
    }

    /** The value of the description's line starting {@code key}, or null. */
    private static String value(Path file, String key) {
        try {
            for (String line : Files.readAllLines(description(file), StandardCharsets.UTF_8)) {
                if (line.startsWith(key)) {
                    return line.substring(key.length()).strip();
                }
            }
        } catch (IOException e) {
            return null;
        }
        return null;
    }

    /** The RMSE of the reference's own noise, from the {@value #NOISE_KEY} line of its description. */
    OptionalDouble noise(Path file) {
        String value = value(file, NOISE_KEY);
        try {
            double v = value == null ? Double.NaN : Double.parseDouble(value);
            return v >= 0 && Double.isFinite(v) ? OptionalDouble.of(v) : OptionalDouble.empty();
        } catch (NumberFormatException e) {
            return OptionalDouble.empty();
        }
    }

    static final String NOISE_KEY = "noise-rmse=";

    private static Path description(Path file) {
        return file.resolveSibling(file.getFileName().toString().replaceFirst("\\.pfm$", ".txt"));
    }
}
