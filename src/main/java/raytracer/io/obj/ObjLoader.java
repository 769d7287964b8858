package raytracer.io.obj;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.zip.GZIPInputStream;
import java.util.zip.ZipException;
import raytracer.image.FileKind;
import raytracer.shapes.Triangle;
import raytracer.shapes.mesh.Growing;
import raytracer.shapes.mesh.ParsedMesh;

/**
 * Loads a Wavefront OBJ file (optionally gzip-compressed, {@code .gz}) into one {@link ParsedMesh}. Each
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
    private final Path file;
    private final String name;
    private final Matcher keyword = ObjPatterns.KEYWORD.matcher("");
    private final Matcher vertex = ObjPatterns.VERTEX.matcher("");
    private final Matcher texcoord = ObjPatterns.TEXCOORD.matcher("");
    private final Matcher normal = ObjPatterns.NORMAL.matcher("");
    private final Matcher vertexPlain = ObjPatterns.VERTEX_PLAIN.matcher("");
    private final Matcher trianglePlain = ObjPatterns.TRIANGLE_PLAIN.matcher("");
    private final Matcher named = ObjPatterns.NAMED.matcher("");

    private final Growing.Doubles positions = new Growing.Doubles();
    private final Growing.Floats texcoords = new Growing.Floats();
    private final Growing.Floats normals = new Growing.Floats();
    private final List<String> warnings = new ArrayList<>();
    private final FileWarnings fileWarnings;
    private final MaterialUse materials;
    private final Faces faces;
    private int lineNumber;
    /** The text the matchers read, and the line being parsed in it, [lineStart, lineEnd). */
    private CharSequence text = "";
    private int lineStart;
    private int lineEnd;

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
        ParsedMesh mesh = MeshAssembly.build(new ObjArrays(positions, texcoords, normals, faces.cornerV, faces.cornerVt,
                                                            faces.cornerVn, materials.ids()), smoothNormals);
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
        if (chunk.general || chunk.excess > positions.size() / 3) {
            parseLines(text.chars());
            return;
        }
        positions.addAll(chunk.positions, chunk.positionCount);
        faces.addPlain(chunk.corners, chunk.cornerCount);
        materials.addTriangles(chunk.cornerCount / 3);
        lineNumber += chunk.lines;
    }

    /**
     * The lines of a chunk one by one, as BufferedReader.readLine splits them, each matched where
     * it lies in the chunk: only a continued line is copied, to join it to the next.
     */
    private void parseLines(CharSequence chunk) throws ObjException {
        StringBuilder continued = null;
        int start = 0;
        int length = chunk.length();
        while (start < length) {
            int end = start;
            while (end < length && chunk.charAt(end) != '\n' && chunk.charAt(end) != '\r') {
                end++;
            }
            int next = end < length && chunk.charAt(end) == '\r' && end + 1 < length && chunk.charAt(end + 1) == '\n'
                       ? end + 2 : end + 1;
            lineNumber++;
            // a trailing backslash joins the next line to this one
            if (end > start && chunk.charAt(end - 1) == '\\') {
                continued = (continued == null ? new StringBuilder() : continued).append(chunk, start, end - 1).append(' ');
            } else if (continued != null) {
                String line = continued.append(chunk, start, end).toString();
                continued = null;
                parseLine(line, 0, line.length());
            } else {
                parseLine(chunk, start, end);
            }
            start = next;
        }
        if (continued != null) {
            // a backslash on the file's last line continues into nothing: the line ends there
            String line = continued.toString();
            parseLine(line, 0, line.length());
        }
    }

    /** {@code m} set to match the line being parsed. */
    private Matcher onLine(Matcher m) {
        return m.reset(text).region(lineStart, lineEnd);
    }

    /** The line being parsed, as a String: for messages. */
    private String line() {
        return text.subSequence(lineStart, lineEnd).toString();
    }

    private void parseLine(CharSequence chars, int start, int end) throws ObjException {
        text = chars;
        lineStart = start;
        lineEnd = end;
        if (onLine(vertexPlain).matches()) {
            for (int g = 1; g <= 3; g++) {
                positions.add(coordinate(vertexPlain, g));
            }
            return;
        }
        if (onLine(trianglePlain).matches()) {
            faces.at(text, start, end, lineNumber);
            faces.addTriangle(positions.size() / 3, trianglePlain);
            materials.addTriangles(1);
            return;
        }
        if (!onLine(keyword).lookingAt()) {
            return; // blank or comment
        }
        String key = keyword(keyword.start(1), keyword.end(1));
        switch (key) {
            case "v" -> {
                require(onLine(vertex).matches(), "'v x y z' with three numbers");
                for (int g = 1; g <= 3; g++) {
                    positions.add(coordinate(vertex, g));
                }
            }
            case "vt" -> {
                require(onLine(texcoord).matches(), "'vt u [v [w]]' with numbers");
                texcoords.add(floatValue(texcoord, 1, "texture coordinate"));
                texcoords.add(texcoord.start(2) >= 0 ? floatValue(texcoord, 2, "texture coordinate") : 0f);
            }
            case "vn" -> {
                require(onLine(normal).matches(), "'vn x y z' with three numbers");
                for (int g = 1; g <= 3; g++) {
                    normals.add(floatValue(normal, g, "normal component"));
                }
            }
            case "f" -> {
                faces.at(text, start, end, lineNumber);
                materials.addTriangles(faces.read(keyword.end(), positions.size() / 3, texcoords.size() / 2,
                                                  normals.size() / 3));
            }
            case "mtllib", "usemtl", "o", "g", "s" -> {
                onLine(named).matches();
                String argument = Arguments.withoutComment(named.group(2) == null ? "" : named.group(2));
                if (key.equals("mtllib")) {
                    materials.loadLibraries(argument, lineNumber);
                } else if (key.equals("usemtl")) {
                    materials.use(argument, lineNumber, faces.triangles());
                }
            }
            default -> {
                if (!ObjPatterns.ACCEPTED.contains(key)) {
                    fileWarnings.unknownKeyword(lineNumber, key);
                }
            }
        }
    }

    /** The keyword at [start, end) of the line: one of {@link ObjPatterns#KNOWN} without a copy, else a new String. */
    private String keyword(int start, int end) {
        for (String known : ObjPatterns.KNOWN) {
            if (known.length() == end - start && spanIs(known, start)) {
                return known;
            }
        }
        return text.subSequence(start, end).toString();
    }

    private boolean spanIs(String word, int start) {
        for (int i = 0; i < word.length(); i++) {
            if (text.charAt(start + i) != word.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    private double finite(Matcher m, int group) throws ObjException {
        char last = text.charAt(m.end(group) - 1);
        // 'nan', 'inf' and 'infinity' end in a letter other than an exponent's digits
        double v = Character.isLetter(last) ? Double.NaN : Numbers.parseDouble(text, m.start(group), m.end(group));
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
            throw error("expected " + expected + ", got '" + FileWarnings.shown(line(), 60) + "'");
        }
    }

    private ObjException error(String message) {
        return new ObjException(name + ":" + lineNumber + ": " + message);
    }
}
