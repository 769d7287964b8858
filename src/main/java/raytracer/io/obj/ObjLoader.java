package raytracer.io.obj;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.GZIPInputStream;
import java.util.zip.ZipException;
import raytracer.shapes.mesh.Mesh;

/**
 * Loads a Wavefront OBJ file (optionally gzip-compressed, {@code .gz}) into one {@link Mesh}. Each
 * line is recognised by a precompiled pattern whose matcher is reused, and numbers are read from
 * the matched spans; chunks of plain vertex and triangle lines are parsed in parallel
 * ({@link ChunkPipeline}), everything else and every error in file order, so messages name the
 * exact line. Faces with more than three corners are fan-triangulated; negative indices
 * count back from the last vertex. A corner is a (v, vt, vn) triple; when the file has only
 * positions the mesh uses its vertex array as is, otherwise each distinct triple becomes one mesh
 * vertex.
 */
public final class ObjLoader {
    static final String NUMBER = "[-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?";
    /** Also catch nan and inf, to report them as such rather than as garbage. */
    private static final String ANY_NUMBER = "[-+]?(?:(?i:nan|inf(?:inity)?)|(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?)";
    static final Pattern KEYWORD = Pattern.compile("\\s*([^\\s#]+)");
    private static final Pattern VERTEX = Pattern.compile(
        "\\s*v\\s+(" + ANY_NUMBER + ")\\s+(" + ANY_NUMBER + ")\\s+(" + ANY_NUMBER + ")(?:\\s+" + ANY_NUMBER + "){0,4}\\s*(?:#.*)?");
    private static final Pattern TEXCOORD = Pattern.compile(
        "\\s*vt\\s+(" + ANY_NUMBER + ")(?:\\s+(" + ANY_NUMBER + "))?(?:\\s+" + ANY_NUMBER + ")?\\s*(?:#.*)?");
    private static final Pattern NORMAL = Pattern.compile(
        "\\s*vn\\s+(" + ANY_NUMBER + ")\\s+(" + ANY_NUMBER + ")\\s+(" + ANY_NUMBER + ")\\s*(?:#.*)?");
    /** Fast paths for the commonest lines (the dragon is nothing else); on failure the general patterns decide. */
    static final Pattern VERTEX_PLAIN = Pattern.compile("v +(" + NUMBER + ") +(" + NUMBER + ") +(" + NUMBER + ") *");
    static final Pattern TRIANGLE_PLAIN = Pattern.compile("f +(\\d+) +(\\d+) +(\\d+) *");
    private static final Pattern FACE = Pattern.compile("\\s*f((?:\\s+[-+]?\\d+(?:/[-+]?\\d*(?:/[-+]?\\d+)?)?)+)\\s*(?:#.*)?");
    private static final Pattern CORNER = Pattern.compile("([-+]?\\d+)(?:/([-+]?\\d*)(?:/([-+]?\\d+))?)?");
    private static final Pattern NAMED = Pattern.compile("\\s*(mtllib|usemtl|o|g|s)(?:\\s+(.*?))?\\s*");
    private static final Set<String> ACCEPTED = Set.of("l", "p", "cstype", "deg", "curv", "surf", "parm", "end",
                                                      "vp", "shadow_obj", "trace_obj", "lod", "bevel", "c_interp", "d_interp");

    private final Path file;
    private final String name;
    private final Matcher keyword = KEYWORD.matcher("");
    private final Matcher vertex = VERTEX.matcher("");
    private final Matcher texcoord = TEXCOORD.matcher("");
    private final Matcher normal = NORMAL.matcher("");
    private final Matcher face = FACE.matcher("");
    private final Matcher vertexPlain = VERTEX_PLAIN.matcher("");
    private final Matcher trianglePlain = TRIANGLE_PLAIN.matcher("");
    private final Matcher corner = CORNER.matcher("");
    private final Matcher named = NAMED.matcher("");

    private final Buffers.Doubles positions = new Buffers.Doubles();
    private final Buffers.Floats texcoords = new Buffers.Floats();
    private final Buffers.Floats normals = new Buffers.Floats();
    /** Corner triples of all triangles: v always, vt and vn once any corner has them (else null). */
    private final Buffers.Ints cornerV = new Buffers.Ints();
    private Buffers.Ints cornerVt;
    private Buffers.Ints cornerVn;
    private final Buffers.Ints materialIds = new Buffers.Ints();
    private final int[] faceV = new int[64];
    private final int[] faceVt = new int[64];
    private final int[] faceVn = new int[64];

    private final List<ObjMaterial> materials = new ArrayList<>();
    private final Map<String, Integer> materialIndex = new HashMap<>();
    private final Map<String, ObjMaterial> library = new HashMap<>();
    private final List<String> warnings = new ArrayList<>();
    private final Set<String> warnedKeywords = new HashSet<>();
    private int currentMaterial = -1;
    private boolean materialsUsed;
    private int lineNumber;
    /** The line being parsed, whose spans the matchers' groups point into. */
    private String line = "";

    private ObjLoader(Path file) {
        this.file = file;
        this.name = file.toString();
    }

    /**
     * Loads {@code file}; with {@code smoothNormals}, a mesh without normals gets angle-weighted
     * vertex normals, otherwise it stays flat-shaded.
     */
    public static ObjModel load(Path file, boolean smoothNormals) throws ObjException {
        return new ObjLoader(file).read(smoothNormals);
    }

    private ObjModel read(boolean smoothNormals) throws ObjException {
        try (InputStream raw = Files.newInputStream(file);
             InputStream in = name.endsWith(".gz") ? new GZIPInputStream(raw, 1 << 16) : raw) {
            ChunkPipeline.run(new LineChunks(in), this::merge);
        } catch (NoSuchFileException e) {
            throw new ObjException("cannot read mesh " + name + ": no such file");
        } catch (EOFException | ZipException e) {
            throw new ObjException(name + ": the gzip data is truncated or corrupt (" + e.getMessage() + ")");
        } catch (IOException e) {
            throw new ObjException("cannot read mesh " + name + ": " + e.getMessage(), e);
        }
        if (cornerV.size == 0) {
            throw new ObjException(name + ": no faces (an OBJ mesh needs 'f' lines)");
        }
        return new ObjModel(MeshAssembly.build(this, smoothNormals), List.copyOf(materials), List.copyOf(warnings));
    }

    /**
     * Appends a chunk's plain parse, if it had one and its faces name only vertices defined so far;
     * otherwise parses its lines here, in order, with everything read before them.
     */
    private void merge(String text, PlainChunk chunk) throws ObjException {
        if (chunk.general || chunk.excess > positions.size / 3) {
            parseLines(text);
            return;
        }
        positions.addAll(chunk.positions, chunk.positionCount);
        cornerV.addAll(chunk.corners, chunk.cornerCount);
        // as parsePlainTriangle would have added them, one by one
        if (cornerVt != null) {
            cornerVt.fill(-1, chunk.cornerCount);
        }
        if (cornerVn != null) {
            cornerVn.fill(-1, chunk.cornerCount);
        }
        if (materialsUsed) {
            materialIds.fill(currentMaterial, chunk.cornerCount / 3);
        }
        lineNumber += chunk.lines;
    }

    /** The lines of a chunk one by one, as BufferedReader.readLine splits them. */
    private void parseLines(String text) throws ObjException {
        StringBuilder continued = null;
        int start = 0;
        int length = text.length();
        while (start < length) {
            int end = start;
            while (end < length && text.charAt(end) != '\n' && text.charAt(end) != '\r') {
                end++;
            }
            String line = text.substring(start, end);
            start = end < length && text.charAt(end) == '\r' && end + 1 < length && text.charAt(end + 1) == '\n'
                    ? end + 2 : end + 1;
            lineNumber++;
            // a trailing backslash joins the next line to this one
            if (line.endsWith("\\")) {
                continued = (continued == null ? new StringBuilder() : continued).append(line, 0, line.length() - 1).append(' ');
                continue;
            }
            if (continued != null) {
                line = continued.append(line).toString();
                continued = null;
            }
            parseLine(line);
        }
        if (continued != null) {
            // a backslash on the file's last line continues into nothing: the line ends there
            parseLine(continued.toString());
        }
    }

    private void parseLine(String text) throws ObjException {
        line = text;
        if (vertexPlain.reset(text).matches()) {
            for (int g = 1; g <= 3; g++) {
                positions.add(finite(vertexPlain, g));
            }
            return;
        }
        if (trianglePlain.reset(text).matches()) {
            parsePlainTriangle();
            return;
        }
        if (!keyword.reset(text).lookingAt()) {
            return; // blank or comment
        }
        String key = keyword.group(1);
        switch (key) {
            case "v" -> {
                require(vertex.reset(text).matches(), "'v x y z' with three numbers");
                for (int g = 1; g <= 3; g++) {
                    positions.add(finite(vertex, g));
                }
            }
            case "vt" -> {
                require(texcoord.reset(text).matches(), "'vt u [v [w]]' with numbers");
                texcoords.add((float) finite(texcoord, 1));
                texcoords.add(texcoord.start(2) >= 0 ? (float) finite(texcoord, 2) : 0f);
            }
            case "vn" -> {
                require(normal.reset(text).matches(), "'vn x y z' with three numbers");
                for (int g = 1; g <= 3; g++) {
                    normals.add((float) finite(normal, g));
                }
            }
            case "f" -> {
                require(face.reset(text).matches(), "'f' and at least 3 corners 'v', 'v/vt', 'v//vn' or 'v/vt/vn'");
                parseFace(face.start(1), face.end(1));
            }
            case "mtllib", "usemtl", "o", "g", "s" -> {
                named.reset(text).matches();
                String argument = named.group(2) == null ? "" : named.group(2);
                if (key.equals("mtllib")) {
                    loadLibraries(argument);
                } else if (key.equals("usemtl")) {
                    useMaterial(argument);
                }
            }
            default -> {
                if (!ACCEPTED.contains(key) && warnedKeywords.add(key)) {
                    warnings.add(name + ":" + lineNumber + ": unknown keyword '" + key + "' ignored (reported once)");
                }
            }
        }
    }

    /** "f a b c" with positive indices: no corner loop, no fan. */
    private void parsePlainTriangle() throws ObjException {
        int count = positions.size / 3;
        for (int g = 1; g <= 3; g++) {
            faceV[g - 1] = resolve(trianglePlain, g, count, "vertex");
            faceVt[g - 1] = -1;
            faceVn[g - 1] = -1;
        }
        addCorner(0);
        addCorner(1);
        addCorner(2);
        if (materialsUsed) {
            materialIds.add(currentMaterial);
        }
    }

    private void parseFace(int from, int to) throws ObjException {
        int count = 0;
        boolean hasVt = false;
        boolean hasVn = false;
        corner.reset(line).region(from, to);
        while (corner.find()) {
            if (count == faceV.length) {
                throw error("a face with more than " + faceV.length + " corners");
            }
            faceV[count] = resolve(corner, 1, positions.size / 3, "vertex");
            faceVt[count] = corner.start(2) < corner.end(2) ? resolve(corner, 2, texcoords.size / 2, "texture coordinate") : -1;
            faceVn[count] = corner.start(3) >= 0 ? resolve(corner, 3, normals.size / 3, "normal") : -1;
            hasVt |= faceVt[count] >= 0;
            hasVn |= faceVn[count] >= 0;
            count++;
        }
        if (count < 3) {
            throw error("a face needs at least 3 vertices, got " + count);
        }
        if (hasVt && cornerVt == null) {
            cornerVt = new Buffers.Ints();
            cornerVt.fill(-1, cornerV.size);
        }
        if (hasVn && cornerVn == null) {
            cornerVn = new Buffers.Ints();
            cornerVn.fill(-1, cornerV.size);
        }
        // fan: (0, i, i + 1)
        for (int i = 1; i + 1 < count; i++) {
            addCorner(0);
            addCorner(i);
            addCorner(i + 1);
            if (materialsUsed) {
                materialIds.add(currentMaterial);
            }
        }
    }

    private void addCorner(int i) {
        cornerV.add(faceV[i]);
        if (cornerVt != null) {
            cornerVt.add(faceVt[i]);
        }
        if (cornerVn != null) {
            cornerVn.add(faceVn[i]);
        }
    }

    /** A 0-based index from a 1-based or negative (relative) OBJ index, checked against the count so far. */
    private int resolve(Matcher m, int group, int count, String what) throws ObjException {
        int index = Numbers.parseInt(line, m.start(group), m.end(group));
        int resolved = index > 0 ? index - 1 : count + index;
        if (index == 0 || resolved < 0 || resolved >= count) {
            throw error(what + " index " + index + " is out of range (" + count + " defined so far; indices are 1.."
                        + count + " or -1..-" + count + ")");
        }
        return resolved;
    }

    private double finite(Matcher m, int group) throws ObjException {
        char last = line.charAt(m.end(group) - 1);
        // 'nan', 'inf' and 'infinity' end in a letter other than an exponent's digits
        double v = Character.isLetter(last) ? Double.NaN : Numbers.parseDouble(line, m.start(group), m.end(group));
        if (!Double.isFinite(v)) {
            throw error("coordinate '" + m.group(group) + "' is not a finite number");
        }
        return v;
    }

    private void require(boolean matched, String expected) throws ObjException {
        if (!matched) {
            String shown = line.strip();
            throw error("expected " + expected + ", got '" + (shown.length() > 60 ? shown.substring(0, 60) + "..." : shown) + "'");
        }
    }

    private ObjException error(String message) {
        return new ObjException(name + ":" + lineNumber + ": " + message);
    }

    private void loadLibraries(String argument) {
        Path folder = file.toAbsolutePath().getParent();
        for (String lib : argument.split("\\s+")) {
            if (lib.isEmpty()) {
                continue;
            }
            Path path = folder.resolve(lib).normalize();
            try {
                library.putAll(MtlLoader.load(path, warnings));
            } catch (ObjException e) {
                warnings.add(name + ":" + lineNumber + ": " + e.getMessage() + "; its materials fall back to grey");
            }
        }
    }

    private void useMaterial(String materialName) {
        if (!materialsUsed) {
            materialsUsed = true;
            // faces before the first usemtl get the fallback material
            int before = cornerV.size / 3;
            if (before > 0) {
                currentMaterial = materialId("(default)");
                materialIds.fill(currentMaterial, before);
            }
        }
        currentMaterial = materialId(materialName);
    }

    private int materialId(String materialName) {
        Integer known = materialIndex.get(materialName);
        if (known != null) {
            return known;
        }
        ObjMaterial m = library.get(materialName);
        if (m == null) {
            if (!materialName.equals("(default)")) {
                warnings.add(name + ":" + lineNumber + ": material '" + materialName + "' is not defined in any mtllib; using grey");
            }
            m = ObjMaterial.fallback(materialName);
        }
        materials.add(m);
        materialIndex.put(materialName, materials.size() - 1);
        return materials.size() - 1;
    }

    // ---- read by MeshAssembly ----
    Buffers.Doubles positions() {
        return positions;
    }

    Buffers.Floats texcoords() {
        return texcoords;
    }

    Buffers.Floats normals() {
        return normals;
    }

    Buffers.Ints cornerV() {
        return cornerV;
    }

    Buffers.Ints cornerVt() {
        return cornerVt;
    }

    Buffers.Ints cornerVn() {
        return cornerVn;
    }

    int[] materialIds() {
        return materialsUsed ? materialIds.toArray() : null;
    }
}
