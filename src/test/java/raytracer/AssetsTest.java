package raytracer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.DigestInputStream;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The repository is self-contained: every file of assets/ is listed in assets/SOURCES.md with its
 * SHA-256 (so its provenance is written down and the bytes are the ones described), every listed
 * file exists, and no scene reads a file outside the repository.
 */
class AssetsTest {
    private static final Path ASSETS = Path.of("assets");
    private static final Pattern CHECKSUM_LINE = Pattern.compile("(?m)^([0-9a-f]{64})  (\\S+)$");

    @Test
    void sourcesListsEveryAssetWithItsChecksum() throws IOException, NoSuchAlgorithmException {
        Map<String, String> listed = new TreeMap<>();
        Matcher m = CHECKSUM_LINE.matcher(Files.readString(ASSETS.resolve("SOURCES.md")));
        while (m.find()) {
            listed.put(m.group(2), m.group(1));
        }
        Map<String, String> present = new TreeMap<>();
        try (Stream<Path> files = Files.walk(ASSETS)) {
            for (Path file : (Iterable<Path>) files.filter(Files::isRegularFile)::iterator) {
                String name = ASSETS.relativize(file).toString().replace('\\', '/');
                if (!name.equals("SOURCES.md")) {
                    present.put(name, sha256(file));
                }
            }
        }
        assertFalse(present.isEmpty(), "assets/ must be found from the project folder");
        assertEquals(listed.keySet(), present.keySet(), "files of assets/ against the checksum list in assets/SOURCES.md");
        present.forEach((name, hash) -> assertEquals(listed.get(name), hash, "SHA-256 of assets/" + name));
    }

    @Test
    void scenesReadNothingOutsideTheRepository() throws IOException {
        try (Stream<Path> scenes = Files.list(Path.of("scenes"))) {
            for (Path scene : (Iterable<Path>) scenes::iterator) {
                String text = Files.readString(scene);
                assertFalse(text.contains("../../"), scene + " reaches outside the repository");
                Matcher file = Pattern.compile("file: ([^,}\\s]+)").matcher(text);
                while (file.find()) {
                    Path target = scene.getParent().resolve(file.group(1)).normalize();
                    assertTrue(Files.isRegularFile(target), scene + " reads " + file.group(1) + ", which is not in the repository");
                }
            }
        }
    }

    private static String sha256(Path file) throws IOException, NoSuchAlgorithmException {
        MessageDigest digest = MessageDigest.getInstance("SHA-256");
        try (InputStream in = new DigestInputStream(Files.newInputStream(file), digest)) {
            in.transferTo(java.io.OutputStream.nullOutputStream());
        }
        return HexFormat.of().formatHex(digest.digest());
    }
}
