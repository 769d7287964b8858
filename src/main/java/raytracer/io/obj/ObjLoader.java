package raytracer.io.obj;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.GZIPInputStream;
import java.util.zip.ZipException;
import raytracer.image.FileKind;
import raytracer.shapes.Triangle;
import raytracer.shapes.mesh.Mesh;

/**
 * Loads a Wavefront OBJ file (optionally gzip-compressed, {@code .gz}) into one {@link Mesh}. Each
 * line is recognised by a precompiled pattern whose matcher is reused, and numbers are read from
 * the matched spans; chunks of plain vertex and triangle lines are parsed in parallel
 * ({@link ChunkPipeline}), everything else and every error in file order, so messages name the
 * exact line. Faces of any number of corners are fan-triangulated; negative indices count
 * back from the last vertex. A corner is a (v, vt, vn) triple; when the file has only
 * positions the mesh uses its vertex array as is, otherwise each distinct triple becomes one mesh
 * vertex. Text that is not UTF-8 is read as ISO-8859-1 ({@link Decoding}); what other tools
 * tolerate is a warning ({@link FileWarnings}), a line that does not parse an error.
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
    private static final Pattern NAMED = Pattern.compile("\\s*(mtllib|usemtl|o|g|s)(?:\\s+(.*?))?\\s*");
    /** Statements of the OBJ specification that a mesh of triangles has no use for. */
    private static final Set<String> ACCEPTED = Set.of("l", "p", "cstype", "deg", "curv", "curv2", "surf", "parm", "end",
        "vp", "bmat", "step", "trim", "hole", "scrv", "sp", "con", "mg", "call", "csh", "maplib", "usemap", "ctech",
        "stech", "shadow_obj", "trace_obj", "lod", "bevel", "c_interp", "d_interp");

    private final Path file;
    private final String name;
    private final Matcher keyword = KEYWORD.matcher("");
    private final Matcher vertex = VERTEX.matcher("");
    private final Matcher texcoord = TEXCOORD.matcher("");
    private final Matcher normal = NORMAL.matcher("");
    private final Matcher vertexPlain = VERTEX_PLAIN.matcher("");
    private final Matcher trianglePlain = TRIANGLE_PLAIN.matcher("");
    private final Matcher named = NAMED.matcher("");

    private final Buffers.Doubles positions = new Buffers.Doubles();
    private final Buffers.Floats texcoords = new Buffers.Floats();
    private final Buffers.Floats normals = new Buffers.Floats();
    private final List<String> warnings = new ArrayList<>();
    private final FileWarnings fileWarnings;
    private final MaterialUse materials;
    private final Faces faces;
    private int lineNumber;
    /** The line being parsed, whose spans the matchers' groups point into. */
    private String line = "";

    private ObjLoader(Path file) {
        this.file = file;
        this.name = file.toString();
        this.fileWarnings = new FileWarnings(name, warnings);
        this.materials = new MaterialUse(file, warnings);
        this.faces = new Faces(name, fileWarnings);
    }

    /**
     * Loads {@code file}; with {@code smoothNormals}, a mesh without normals gets angle-weighted
     * vertex normals, otherwise it stays flat-shaded.
     */
    public static ObjModel load(Path file, boolean smoothNormals) throws ObjException {
        return new ObjLoader(file).read(smoothNormals);
    }

    private ObjModel read(boolean smoothNormals) throws ObjException {
        String notRegular = FileKind.notRegular(file);
        if (notRegular != null) {
            throw new ObjException("cannot read mesh " + name + ": " + notRegular);
        }
        try (InputStream raw = Files.newInputStream(file);
             InputStream in = name.endsWith(".gz") ? new GZIPInputStream(raw, 1 << 16) : raw) {
            ChunkPipeline.run(new LineChunks(in), this::merge);
        } catch (NoSuchFileException e) {
            throw new ObjException("cannot read mesh " + name + ": no such file");
        } catch (EOFException | ZipException e) {
            throw new ObjException(name + (isEmpty() ? ": the file is empty (no gzip data)"
                : ": the gzip data is truncated or corrupt (" + (e.getMessage() != null ? e.getMessage() : "it ends early") + ")"));
        } catch (IOException e) {
            throw new ObjException("cannot read mesh " + name + ": " + e.getMessage(), e);
        }
        if (faces.faces == 0) {
            throw new ObjException(name + ": no faces (an OBJ mesh needs 'f' lines)");
        }
        fileWarnings.finish();
        Mesh mesh = MeshAssembly.build(this, smoothNormals);
        List<ObjMaterial> used = materials.materials();
        return new ObjModel(mesh, used, List.copyOf(warnings), faces.faces, faces.ngons, materials.libraries(),
                            OpenSheets.of(mesh, used));
    }

    private boolean isEmpty() {
        try {
            return Files.size(file) == 0;
        } catch (IOException e) {
            return false;
        }
    }

    /**
     * Appends a chunk's plain parse, if it had one and its faces name only vertices defined so far;
     * otherwise parses its lines here, in order, with everything read before them.
     */
    private void merge(Decoding.Text text, PlainChunk chunk) throws ObjException {
        if (text.latin1From() >= 0) {
            int at = lineNumber + 1 + text.latin1Line();
            fileWarnings.tally("latin1", at, n -> "a byte that is not UTF-8; this part of the file is read as ISO-8859-1 (Latin-1)");
        }
        if (chunk.general || chunk.excess > positions.size / 3) {
            parseLines(text.text());
            return;
        }
        positions.addAll(chunk.positions, chunk.positionCount);
        faces.addPlain(chunk.corners, chunk.cornerCount);
        materials.addTriangles(chunk.cornerCount / 3);
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
                positions.add(coordinate(vertexPlain, g));
            }
            return;
        }
        if (trianglePlain.reset(text).matches()) {
            faces.addTriangle(text, lineNumber, positions.size / 3, trianglePlain);
            materials.addTriangles(1);
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
                    positions.add(coordinate(vertex, g));
                }
            }
            case "vt" -> {
                require(texcoord.reset(text).matches(), "'vt u [v [w]]' with numbers");
                texcoords.add(floatValue(texcoord, 1, "texture coordinate"));
                texcoords.add(texcoord.start(2) >= 0 ? floatValue(texcoord, 2, "texture coordinate") : 0f);
            }
            case "vn" -> {
                require(normal.reset(text).matches(), "'vn x y z' with three numbers");
                for (int g = 1; g <= 3; g++) {
                    normals.add(floatValue(normal, g, "normal component"));
                }
            }
            case "f" -> materials.addTriangles(faces.read(text, keyword.end(), lineNumber, positions.size / 3,
                                                          texcoords.size / 2, normals.size / 3));
            case "mtllib", "usemtl", "o", "g", "s" -> {
                named.reset(text).matches();
                String argument = Arguments.withoutComment(named.group(2) == null ? "" : named.group(2));
                if (key.equals("mtllib")) {
                    materials.loadLibraries(argument, lineNumber);
                } else if (key.equals("usemtl")) {
                    materials.use(argument, lineNumber, faces.triangles());
                }
            }
            default -> {
                if (!ACCEPTED.contains(key)) {
                    fileWarnings.unknownKeyword(lineNumber, key);
                }
            }
        }
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

    /** A vertex coordinate: finite, and within what a triangle holds ({@link Triangle#MAX_COORDINATE}). */
    private double coordinate(Matcher m, int group) throws ObjException {
        double v = finite(m, group);
        if (Math.abs(v) > Triangle.MAX_COORDINATE) {
            throw error("coordinate '" + m.group(group) + "' is larger than " + Triangle.MAX_COORDINATE + ", the most a "
                        + "triangle's vertex may have (its edges' cross product must square to a double)");
        }
        return v;
    }

    /** A value kept as a float (normals, texture coordinates): past the float range it would be infinite, a normal NaN. */
    private float floatValue(Matcher m, int group, String what) throws ObjException {
        double v = finite(m, group);
        if (Math.abs(v) > Float.MAX_VALUE) {
            throw error(what + " '" + m.group(group) + "' is beyond the largest float ("
                        + String.format(java.util.Locale.ROOT, "%.6g", Float.MAX_VALUE) + ")");
        }
        return (float) v;
    }

    private void require(boolean matched, String expected) throws ObjException {
        if (!matched) {
            throw error("expected " + expected + ", got '" + FileWarnings.shown(line, 60) + "'");
        }
    }

    private ObjException error(String message) {
        return new ObjException(name + ":" + lineNumber + ": " + message);
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
        return faces.cornerV;
    }

    Buffers.Ints cornerVt() {
        return faces.cornerVt;
    }

    Buffers.Ints cornerVn() {
        return faces.cornerVn;
    }

    int[] materialIds() {
        return materials.ids();
    }
}
