package raytracer.cache;

import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import raytracer.image.FileKind;
import raytracer.image.Film;
import raytracer.image.ImageWriters;
import raytracer.image.IoReason;

/**
 * Where the convergence benchmark keeps the references it renders itself, so the next run reuses
 * them. An entry, {@code <scene name>-<key>.ref} ({@link EntryName}), is one file:
 *
 * <pre>
 *   8 bytes magic "RTREF", int {@link #VERSION}, long {@link Checksum} of every byte after it
 *   int length, the description (UTF-8 text: what was rendered, how, and the noise of the average)
 *   the image as {@code render -o x.pfm} writes it (the linear image times the scene's exposure)
 * </pre>
 *
 * so that it is written at once (one rename), and an entry is used only when its bytes still have
 * their checksum and every pixel is finite. The key is the {@link Checksum} of the scene file's
 * bytes, every setting of the reference render and the content of every file the scene reads
 * (meshes, MTL files, textures); the renderer's own code is not in it, so delete the folder after
 * changing that. The folder is a {@link CacheFolder}: it may hold the user's files, which are never
 * touched; there is no cap (a reference is rendered for minutes and takes a few MB).
 */
public final class ReferenceCache {
    /** The layout above: add 1 when it changes, so that older entries are rendered again (2: one file, not a .pfm and a .txt). */
    static final int VERSION = 2;
    /** The first bytes of every entry, by which the cache knows its own files among others in its folder. */
    static final byte[] MAGIC_BYTES = {'R', 'T', 'R', 'E', 'F', 0, 0, 0};
    static final String ENTRY_NAME = EntryName.pattern("ref");
    /** The description's line that holds the RMSE of the reference's own noise. */
    static final String NOISE_KEY = "noise-rmse=";
    /** Magic, version and checksum: what the checksum does not cover. */
    private static final int PREAMBLE = 8 + 4 + 8;

    private final CacheFolder folder;

    public ReferenceCache(Path dir) {
        this.folder = new CacheFolder(dir, ENTRY_NAME, MAGIC_BYTES);
    }

    /** $XDG_CACHE_HOME/raytracer/references, or ~/.cache/raytracer/references. */
    public static Path defaultDir(Map<String, String> environment, String home) {
        return CacheHome.folder(environment, home, "references");
    }

    /** A reference as cached: the image and the RMSE of its own noise. */
    public record Reference(Film film, double noiseRmse) {
    }

    /**
     * The entry of a reference of {@code sceneName} (for people to recognise it), rendered from
     * {@code sceneBytes} with {@code settings} (one line each, in a fixed order).
     */
    public Path file(String sceneName, byte[] sceneBytes, String settings) {
        int dot = sceneName.lastIndexOf('.');
        String stem = dot > 0 ? sceneName.substring(0, dot) : sceneName;
        String identity = "scene " + sceneBytes.length + " " + Checksum.hex(Checksum.of(sceneBytes)) + "\n" + settings;
        return folder.dir().resolve(EntryName.of(stem, identity, "ref"));
    }

    /**
     * The cached reference, if there is one and it is as stored. Anything else counts as none, to
     * be rendered again; {@code why} is told why when a file was there (but for one of another
     * version, which every entry becomes after an upgrade).
     */
    public Optional<Reference> load(Path file, Consumer<String> why) {
        if (!Files.isRegularFile(file)) {
            return Optional.empty();
        }
        try {
            byte[] bytes = Files.readAllBytes(file);
            ByteBuffer in = ByteBuffer.wrap(bytes);
            if (bytes.length < PREAMBLE + 4 || !Arrays.equals(bytes, 0, MAGIC_BYTES.length, MAGIC_BYTES, 0, MAGIC_BYTES.length)) {
                why.accept("is not a reference of this program");
                return Optional.empty();
            }
            if (in.getInt(MAGIC_BYTES.length) != VERSION) {
                return Optional.empty();
            }
            int length = in.getInt(PREAMBLE);
            if (in.getLong(MAGIC_BYTES.length + 4) != Checksum.of(bytes, PREAMBLE, bytes.length - PREAMBLE)
                || length < 0 || length > bytes.length - PREAMBLE - 4) {
                why.accept("does not match its checksum");
                return Optional.empty();
            }
            int image = PREAMBLE + 4 + length;
            String description = new String(bytes, PREAMBLE + 4, length, StandardCharsets.UTF_8);
            Film film = ImageWriters.readPfm(Arrays.copyOfRange(bytes, image, bytes.length), file);
            if (!finite(film)) {
                why.accept("holds a pixel that is not a finite number");
                return Optional.empty();
            }
            double noise = noise(description);
            if (!(noise >= 0 && Double.isFinite(noise))) {
                why.accept("does not record its own noise");
                return Optional.empty();
            }
            CacheFolder.markUsed(file);
            return Optional.of(new Reference(film, noise));
        } catch (IOException e) {
            why.accept("cannot be read (" + IoReason.of(e) + ")");
            return Optional.empty();
        }
    }

    private static boolean finite(Film film) {
        for (int y = 0; y < film.height(); y++) {
            for (int x = 0; x < film.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    if (!Float.isFinite(film.get(x, y, c))) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    /** The value of the description's {@value #NOISE_KEY} line, or NaN. */
    private static double noise(String description) {
        for (String line : description.split("\n")) {
            if (line.startsWith(NOISE_KEY)) {
                try {
                    return Double.parseDouble(line.substring(NOISE_KEY.length()).strip());
                } catch (NumberFormatException e) {
                    return Double.NaN;
                }
            }
        }
        return Double.NaN;
    }

    /**
     * Fails when something other than a folder is where the references are kept: found before a
     * reference is rendered, not after.
     */
    public void checkFolder() throws IOException {
        FileKind kind = FileKind.of(folder.dir());
        if (kind != FileKind.DIRECTORY && kind != FileKind.MISSING) {
            throw new IOException("cannot keep references in " + folder.dir() + ": it is " + kind.words() + ", not a folder");
        }
    }

    /**
     * Stores a reference (in .pfm units already), the RMSE of its own noise and its description
     * (lines a person reads), creating the folder if needed.
     */
    public void store(Path file, Film film, double noiseRmse, String description) throws IOException {
        checkFolder();
        byte[] text = (description + NOISE_KEY + noiseRmse + "\n").getBytes(StandardCharsets.UTF_8);
        byte[] image = ImageWriters.pfmBytes(film, 1);
        ByteBuffer covered = ByteBuffer.allocate(4 + text.length + image.length).putInt(text.length).put(text).put(image);
        long checksum = Checksum.of(covered.array());
        // no cap: what trimming is left to do, removing a killed writer's temporary file, may fail harmlessly
        folder.store(file, stream -> {
            DataOutputStream out = new DataOutputStream(stream);
            out.write(MAGIC_BYTES);
            out.writeInt(VERSION);
            out.writeLong(checksum);
            out.write(covered.array());
            out.flush();
        }, Long.MAX_VALUE);
    }
}
