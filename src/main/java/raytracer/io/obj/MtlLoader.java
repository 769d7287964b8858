package raytracer.io.obj;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import raytracer.image.FileKind;

/**
 * Reads an MTL library: {@code newmtl} blocks with Kd, Ks, Ka, Ke, Ns, d / Tr, Ni, illum, map_Kd and
 * map_Bump / bump / norm (texture options, before or after the file name, are read or skipped:
 * {@link TextureMap}). Unknown keys, values that are not numbers, missing texture files and bytes
 * that are not UTF-8 become warnings, never failures.
 */
final class MtlLoader {
    /** Far more than any material library; a path to something else is refused before it is read. */
    static final long MAX_BYTES = 64L << 20;
    private static final Pattern LINE = Pattern.compile("\\s*([^\\s#]\\S*)(?:\\s+(.*?))?\\s*");
    private static final Pattern COLOR = Pattern.compile("(" + ObjPatterns.NUMBER + ")(?:\\s+(" + ObjPatterns.NUMBER + ")\\s+(" + ObjPatterns.NUMBER + "))?");
    private static final Pattern SCALAR = Pattern.compile(ObjPatterns.NUMBER);
    private static final Set<String> KNOWN = Set.of("Kd", "Ks", "Ka", "Ke", "Ns", "d", "Tr", "Ni", "illum", "map_Kd",
        "map_Bump", "map_bump", "bump", "norm");
    /** Keys of the specification and of common extensions (PBR) that these materials do not use. */
    private static final Set<String> IGNORED = Set.of("Tf", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "Km",
        "map_Ka", "map_Ks", "map_Ke", "map_Ns", "map_d", "map_Tr", "map_Pr", "map_Pm", "map_Ps", "map_aniso", "map_refl",
        "disp", "decal", "refl", "sharpness", "Tr_", "Kt");

    private MtlLoader() {
    }

    static Map<String, ObjMaterial> load(Path file, List<String> warnings) throws ObjException {
        return parse(file, read(file), warnings);
    }

    /**
     * The materials of a library's text: what cannot be read is a warning, a value out of range
     * (a negative or infinite colour, d past 1, ...) an ObjException naming the file and line.
     */
    static Map<String, ObjMaterial> parse(Path file, Decoding.Text decoded, List<String> warnings) throws ObjException {
        FileWarnings warn = new FileWarnings(file.toString(), warnings);
        if (decoded.latin1From() >= 0) {
            warn.add(decoded.latin1Line() + 1, "a byte that is not UTF-8; the file is read as ISO-8859-1 (Latin-1)");
        }
        List<String> lines = decoded.text().lines().toList();
        Map<String, ObjMaterial> result = new LinkedHashMap<>();
        Builder current = null;
        Matcher line = LINE.matcher("");
        for (int i = 0; i < lines.size(); i++) {
            if (!line.reset(lines.get(i)).matches()) {
                continue; // blank or comment
            }
            String key = line.group(1);
            String value = Arguments.withoutComment(line.group(2) == null ? "" : line.group(2));
            int at = i + 1;
            if (key.equals("newmtl")) {
                if (current != null) {
                    result.put(current.name, current.build());
                }
                current = new Builder(value);
            } else if (!KNOWN.contains(key) && !IGNORED.contains(key)) {
                warn.unknownKeyword(at, key);
            } else if (current == null) {
                warn.tally("before newmtl", at, n -> (n == 1 ? "a statement" : n + " statements") + " before the first newmtl ignored");
            } else {
                read(current, key, value, file, at, warn);
            }
        }
        if (current != null) {
            result.put(current.name, current.build());
        }
        warn.finish();
        return result;
    }

    /** The library's text without a byte-order mark, decoded as {@link Decoding} says. */
    static Decoding.Text read(Path file) throws ObjException {
        try {
            String notRegular = FileKind.notRegular(file);
            if (notRegular != null) {
                throw new ObjException("material library " + file + " is " + notRegular);
            }
            if (Files.exists(file) && Files.size(file) > MAX_BYTES) {
                throw new ObjException("material library " + file + " is larger than " + (MAX_BYTES >> 20) + " MiB");
            }
            byte[] bytes = Files.readAllBytes(file);
            return Decoding.decode(bytes, Decoding.byteOrderMark(bytes, bytes.length), bytes.length);
        } catch (NoSuchFileException e) {
            throw new ObjException("material library " + file + " is missing");
        } catch (IOException e) {
            throw new ObjException("cannot read material library " + file + ": " + e.getMessage());
        }
    }

    private static void read(Builder m, String key, String value, Path file, int at, FileWarnings warn) throws ObjException {
        Range range = new Range(file, at, key, value);
        switch (key) {
            case "Kd" -> m.kd = range.color(color(value, at, warn, m.kd));
            case "Ks" -> m.ks = range.color(color(value, at, warn, m.ks));
            case "Ka" -> m.ka = range.color(color(value, at, warn, m.ka));
            case "Ke" -> m.ke = range.emission(range.color(color(value, at, warn, m.ke)));
            case "Ns" -> m.ns = range.atLeastZero(scalar(value, at, warn, m.ns));
            case "d" -> {
                m.dissolve = range.fraction(scalar(value, at, warn, m.dissolve));
                m.dissolveGiven = true;
            }
            // d wins over Tr whatever their order: some exporters write Tr inverted
            case "Tr" -> m.dissolve = m.dissolveGiven ? m.dissolve : 1 - range.fraction(scalar(value, at, warn, 1 - m.dissolve));
            case "Ni" -> m.ior = range.ior(scalar(value, at, warn, m.ior), m.ior, warn);
            case "illum" -> m.illum = range.illum(scalar(value, at, warn, m.illum));
            case "map_Kd" -> m.mapKd = texture(file, TextureMap.parse(value), at, warn);
            case "map_Bump", "map_bump", "bump", "norm" -> {
                TextureMap map = TextureMap.parse(value);
                m.mapBump = texture(file, map, at, warn);
                m.bumpScale = map.bumpScale();
            }
            default -> {
                // a key of the specification these materials do not use
            }
        }
    }

    /**
     * The ranges of MTL values, as a scene's own materials have them: colours finite and not
     * negative, an emission no brighter than an image holds, d and Tr fractions, illum one of the
     * specification's models 0 to 10. A value out of range is an error at its line; an Ni that is
     * not positive and finite is a warning.
     */
    private record Range(Path file, int line, String key, String value) {
        /** The most a channel may emit: the image holds floats (as a scene's lights, YamlObject.MAX_EMISSION). */
        static final double MAX_EMISSION = Float.MAX_VALUE;

        private ObjException error(String expected, String got) {
            return new ObjException(file + ":" + line + ": " + key + " must be " + expected + ", got " + got);
        }

        double[] color(double[] rgb) throws ObjException {
            for (double c : rgb) {
                if (!(c >= 0) || !Double.isFinite(c)) {
                    throw error("3 finite numbers of at least 0", token(c));
                }
            }
            return rgb;
        }

        double[] emission(double[] rgb) throws ObjException {
            for (double c : rgb) {
                if (c > MAX_EMISSION) {
                    throw error(String.format(Locale.ROOT, "at most %.6g (the largest value an image holds)", MAX_EMISSION),
                                token(c));
                }
            }
            return rgb;
        }

        double atLeastZero(double v) throws ObjException {
            if (!(v >= 0) || !Double.isFinite(v)) {
                throw error("a finite number of at least 0", token(v));
            }
            return v;
        }

        /**
         * Ni when it is an index of refraction, else {@code kept} with a warning: tinyobjloader
         * takes any Ni unchecked, and a value only glass uses should not stop a render.
         */
        double ior(double v, double kept, FileWarnings warn) {
            if (v > 0 && Double.isFinite(v)) {
                return v;
            }
            warn.add(line, key + " must be a finite number greater than 0, got " + token(v) + "; kept the default");
            return kept;
        }

        double fraction(double v) throws ObjException {
            if (!(v >= 0 && v <= 1)) {
                throw error("a number from 0 to 1", token(v));
            }
            return v;
        }

        int illum(double v) throws ObjException {
            if (!(v >= 0 && v <= 10) || v != Math.rint(v)) {
                throw error("a whole number from 0 to 10", token(v));
            }
            return (int) v;
        }

        /** The value as written in the file: the first of its numbers that parses to {@code v}. */
        private String token(double v) {
            for (String word : value.split("\\s+")) {
                try {
                    double parsed = Double.parseDouble(word);
                    if (Double.compare(parsed, v) == 0 || parsed == v) {
                        return word;
                    }
                } catch (NumberFormatException e) {
                    // not this word
                }
            }
            return Double.toString(v);
        }
    }

    private static double[] color(String value, int at, FileWarnings warn, double[] fallback) {
        Matcher m = COLOR.matcher(value);
        if (!m.matches()) {
            warn.add(at, "expected a colour 'r g b', got '" + FileWarnings.shown(value, 40) + "'; kept the default");
            return fallback;
        }
        double r = Double.parseDouble(m.group(1));
        return m.group(2) == null ? new double[] {r, r, r}
                                  : new double[] {r, Double.parseDouble(m.group(2)), Double.parseDouble(m.group(3))};
    }

    private static double scalar(String value, int at, FileWarnings warn, double fallback) {
        if (!SCALAR.matcher(value).matches()) {
            warn.add(at, "expected a number, got '" + FileWarnings.shown(value, 40) + "'; kept the default");
            return fallback;
        }
        return Double.parseDouble(value);
    }

    /** The texture file resolved next to the library; null (with a warning) if missing. */
    private static Path texture(Path library, TextureMap map, int at, FileWarnings warn) {
        if (map.file().isEmpty()) {
            warn.add(at, "expected a texture file name after the options; the material is used without it");
            return null;
        }
        Path path;
        try {
            path = library.toAbsolutePath().getParent().resolve(Arguments.path(map.file())).normalize();
        } catch (InvalidPathException e) {
            warn.add(at, "texture '" + FileWarnings.shown(map.file(), 60) + "' is not a valid path; the material is used without it");
            return null;
        }
        if (!Files.isRegularFile(path)) {
            warn.add(at, "texture " + FileWarnings.shown(path.toString(), 200) + " is missing; the material is used without it");
            return null;
        }
        return path;
    }

    /** Mutable while one newmtl block is read. */
    private static final class Builder {
        final String name;
        double[] kd = {0.8, 0.8, 0.8};
        double[] ks = {0, 0, 0};
        double[] ka = {0, 0, 0};
        double[] ke = {0, 0, 0};
        double ns;
        double dissolve = 1;
        boolean dissolveGiven;
        double ior = 1;
        int illum = 1;
        Path mapKd;
        Path mapBump;
        double bumpScale = 1;

        Builder(String name) {
            this.name = name;
        }

        ObjMaterial build() {
            return new ObjMaterial(name, kd, ks, ka, ke, ns, dissolve, ior, illum, mapKd, mapBump, bumpScale);
        }
    }
}
