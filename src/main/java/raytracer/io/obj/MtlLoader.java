package raytracer.io.obj;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads an MTL library: {@code newmtl} blocks with Kd, Ks, Ka, Ke, Ns, d / Tr, Ni, illum, map_Kd and
 * map_Bump / bump / norm (map options such as {@code -bm 0.5} before the file name are read or
 * skipped). Unknown keys and missing texture files become warnings, never failures.
 */
final class MtlLoader {
    private static final Pattern LINE = Pattern.compile("\\s*(\\S+)(?:\\s+(.*?))?\\s*");
    private static final Pattern COLOR = Pattern.compile("(" + ObjLoader.NUMBER + ")(?:\\s+(" + ObjLoader.NUMBER + ")\\s+(" + ObjLoader.NUMBER + "))?");
    private static final Pattern SCALAR = Pattern.compile(ObjLoader.NUMBER);
    /** Map options: a dash-word followed by its numeric arguments, then the file name. */
    private static final Pattern MAP = Pattern.compile("((?:-\\w+(?:\\s+" + ObjLoader.NUMBER + ")*\\s+)*)(.+)");
    private static final Pattern BUMP_SCALE = Pattern.compile("-bm\\s+(" + ObjLoader.NUMBER + ")");
    private static final Set<String> IGNORED = Set.of("Tf", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor",
        "map_Ka", "map_Ks", "map_Ns", "map_d", "map_Pr", "map_Pm", "disp", "decal", "refl", "sharpness", "Tr_", "Kt");

    private MtlLoader() {
    }

    static Map<String, ObjMaterial> load(Path file, List<String> warnings) throws ObjException {
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new ObjException("material library " + file + " is missing");
        } catch (IOException e) {
            throw new ObjException("cannot read material library " + file + ": " + e.getMessage());
        }
        Map<String, ObjMaterial> result = new LinkedHashMap<>();
        Builder current = null;
        Set<String> warned = new HashSet<>();
        Matcher line = LINE.matcher("");
        for (int i = 0; i < lines.size(); i++) {
            String text = lines.get(i);
            if (text.isBlank() || text.strip().startsWith("#") || !line.reset(text).matches()) {
                continue;
            }
            String key = line.group(1);
            String value = line.group(2) == null ? "" : line.group(2);
            String where = file + ":" + (i + 1);
            if (key.equals("newmtl")) {
                if (current != null) {
                    result.put(current.name, current.build());
                }
                current = new Builder(value);
                continue;
            }
            if (current == null) {
                warnings.add(where + ": '" + key + "' before any newmtl ignored");
                continue;
            }
            switch (key) {
                case "Kd" -> current.kd = color(value, where, warnings, current.kd);
                case "Ks" -> current.ks = color(value, where, warnings, current.ks);
                case "Ka" -> current.ka = color(value, where, warnings, current.ka);
                case "Ke" -> current.ke = color(value, where, warnings, current.ke);
                case "Ns" -> current.ns = scalar(value, where, warnings, current.ns);
                case "d" -> {
                    current.dissolve = scalar(value, where, warnings, current.dissolve);
                    current.dissolveGiven = true;
                }
                // d wins over Tr whatever their order: some exporters write Tr inverted
                case "Tr" -> current.dissolve = current.dissolveGiven ? current.dissolve
                                                 : 1 - scalar(value, where, warnings, 1 - current.dissolve);
                case "Ni" -> current.ior = scalar(value, where, warnings, current.ior);
                case "illum" -> current.illum = (int) scalar(value, where, warnings, current.illum);
                case "map_Kd" -> current.mapKd = texture(file, value, where, warnings);
                case "map_Bump", "map_bump", "bump", "norm" -> {
                    current.mapBump = texture(file, value, where, warnings);
                    Matcher bm = BUMP_SCALE.matcher(value);
                    if (bm.find()) {
                        current.bumpScale = Double.parseDouble(bm.group(1));
                    }
                }
                default -> {
                    if (!IGNORED.contains(key) && warned.add(key)) {
                        warnings.add(where + ": unknown material key '" + key + "' ignored (reported once)");
                    }
                }
            }
        }
        if (current != null) {
            result.put(current.name, current.build());
        }
        return result;
    }

    private static double[] color(String value, String where, List<String> warnings, double[] fallback) {
        Matcher m = COLOR.matcher(value);
        if (!m.matches()) {
            warnings.add(where + ": expected a colour 'r g b', got '" + value + "'; kept the default");
            return fallback;
        }
        double r = Double.parseDouble(m.group(1));
        return m.group(2) == null ? new double[] {r, r, r}
                                  : new double[] {r, Double.parseDouble(m.group(2)), Double.parseDouble(m.group(3))};
    }

    private static double scalar(String value, String where, List<String> warnings, double fallback) {
        if (!SCALAR.matcher(value).matches()) {
            warnings.add(where + ": expected a number, got '" + value + "'; kept the default");
            return fallback;
        }
        return Double.parseDouble(value);
    }

    /** The texture file after any options, resolved next to the library; null (with a warning) if missing. */
    private static Path texture(Path library, String value, String where, List<String> warnings) {
        Matcher m = MAP.matcher(value);
        String name = m.matches() ? m.group(2).strip() : value.strip();
        Path path = library.toAbsolutePath().getParent().resolve(name).normalize();
        if (!Files.isRegularFile(path)) {
            warnings.add(where + ": texture " + path + " is missing; the material is used without it");
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
