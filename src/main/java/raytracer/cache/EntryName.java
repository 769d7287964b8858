package raytracer.cache;

import java.nio.charset.StandardCharsets;

/**
 * How a cache names its entries: {@code <name>-<key>.<extension>}. The name is for people (the
 * mesh file's, the scene's), cut to {@value #NAME_CHARS} plain characters so that the entry's
 * temporary file, which adds to it, still fits a folder entry; the key is the {@link Checksum} of
 * a text naming everything the entry depends on, so that an entry is found again exactly when all
 * of that is the same.
 */
final class EntryName {
    /** The most characters of the name kept. */
    static final int NAME_CHARS = 48;

    private EntryName() {
    }

    /** The entry of {@code name} keyed by {@code identity}. */
    static String of(String name, String identity, String extension) {
        String plain = name.replaceAll("[^A-Za-z0-9._-]", "_");
        if (plain.length() > NAME_CHARS) {
            plain = plain.substring(0, NAME_CHARS);
        }
        return plain + "-" + Checksum.hex(Checksum.of(identity.getBytes(StandardCharsets.UTF_8))) + "." + extension;
    }

    /** A regular expression of every name {@link #of} makes with {@code extension}. */
    static String pattern(String extension) {
        return "[A-Za-z0-9._-]{1," + NAME_CHARS + "}-[0-9a-f]{16}\\." + extension;
    }
}
