package raytracer.io.ply;

import java.io.BufferedInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.zip.GZIPInputStream;
import java.util.zip.ZipException;
import raytracer.shapes.Triangle;
import raytracer.shapes.mesh.Growing;
import raytracer.shapes.mesh.ParsedMesh;
import raytracer.shapes.mesh.SmoothNormals;

/**
 * Loads a PLY file (optionally gzip-compressed, {@code .ply.gz}) into one {@link ParsedMesh}: the
 * {@code vertex} element's x, y, z, its normals nx, ny, nz and texture coordinates (u, v; s, t;
 * texture_u, texture_v) when all of a set are there, and the {@code face} element's vertex_indices
 * (or vertex_index) lists, fan-triangulated. Other properties (colours, a scanner's confidence) and
 * elements are read past, named in one warning. Counts come from the header, which a damaged or
 * hostile file may overstate, so arrays grow as values arrive rather than being sized from it.
 */
public final class PlyLoader {
    /** At most this many values are set aside from a header's count before they arrive. */
    private static final int FIRST_CAPACITY = 1 << 20;
    /** More corners than this in one face is not a scanned mesh's polygon. */
    static final int MAX_CORNERS = 1 << 16;
    /** The most triangle corners a Java int array holds, with room for the VM's header. */
    private static final int MAX_CORNER_INDICES = Integer.MAX_VALUE - 8;

    private final String file;
    private final List<String> warnings = new ArrayList<>();
    private final Set<String> skipped = new LinkedHashSet<>();

    private long vertices = -1;
    private Growing.Doubles positions;
    private float[] normals;
    private float[] uvs;
    private int[] triangles = new int[0];
    private int corners;
    private int faces;
    private boolean facesRead;
    private int ngons;

    private PlyLoader(String file) {
        this.file = file;
    }

    /** Loads {@code file}; with {@code smoothNormals}, a mesh without normals gets angle-weighted vertex normals. */
    public static PlyModel load(Path file, boolean smoothNormals) throws PlyException {
        return new PlyLoader(file.toString()).read(file, smoothNormals);
    }

    private PlyModel read(Path path, boolean smoothNormals) throws PlyException {
        if (Files.exists(path) && !Files.isRegularFile(path)) {
            throw new PlyException("cannot read mesh " + file + ": not a regular file");
        }
        try (InputStream raw = Files.newInputStream(path);
             InputStream in = new BufferedInputStream(file.endsWith(".gz") ? new GZIPInputStream(raw, 1 << 16) : raw, 1 << 16)) {
            PlyHeader header = PlyHeader.read(in, file);
            PlyInput body = PlyInput.of(header.format(), in);
            for (PlyHeader.Element e : header.elements()) {
                switch (e.name()) {
                    case "vertex" -> readVertices(e, body);
                    case "face" -> readFaces(e, body, header);
                    default -> {
                        skipped.add("element '" + PlyHeader.shown(e.name()) + "'");
                        skipElements(e, body);
                    }
                }
            }
        } catch (NoSuchFileException e) {
            throw new PlyException("cannot read mesh " + file + ": no such file");
        } catch (ZipException e) {
            throw new PlyException(file + ": the gzip data is corrupt (" + e.getMessage() + ")");
        } catch (EOFException e) {
            throw new PlyException(file + ": the gzip data is truncated");
        } catch (IOException e) {
            throw new PlyException("cannot read mesh " + file + ": " + e.getMessage(), e);
        }
        if (vertices < 0) {
            throw new PlyException(file + ": no 'vertex' element");
        }
        if (faces == 0) {
            throw new PlyException(file + ": no faces (a PLY mesh needs a 'face' element with vertex_indices)");
        }
        if (!skipped.isEmpty()) {
            warnings.add(file + ": read past " + String.join(", ", skipped) + " (not used)");
        }
        int[] t = Arrays.copyOf(triangles, corners);
        float[] n = normals != null ? normals : smoothNormals ? SmoothNormals.angleWeighted(positions, t) : null;
        return new PlyModel(new ParsedMesh(positions, n, uvs, t, null), List.copyOf(warnings), faces, ngons);
    }

    private void readVertices(PlyHeader.Element e, PlyInput in) throws IOException, PlyException {
        if (vertices >= 0) {
            throw new PlyException(file + ": a second 'vertex' element");
        }
        if (e.count() > Integer.MAX_VALUE / 3) {
            throw new PlyException(file + ": " + e.count() + " vertices; at most " + Integer.MAX_VALUE / 3 + " fit one mesh");
        }
        int x = e.scalar("x");
        int y = e.scalar("y");
        int z = e.scalar("z");
        if (x < 0 || y < 0 || z < 0) {
            throw new PlyException(file + ": the vertex element needs scalar properties x, y and z");
        }
        int nx = e.scalar("nx");
        int ny = e.scalar("ny");
        int nz = e.scalar("nz");
        boolean hasNormals = nx >= 0 && ny >= 0 && nz >= 0;
        int u = e.scalar("u", "s", "texture_u", "texture_s");
        int v = e.scalar("v", "t", "texture_v", "texture_t");
        boolean hasUvs = u >= 0 && v >= 0;
        List<PlyHeader.Property> properties = e.properties();
        // what each property is for: 0-2 position, 3-5 normal, 6-7 uv, -1 read past
        int[] slot = new int[properties.size()];
        Arrays.fill(slot, -1);
        slot[x] = 0;
        slot[y] = 1;
        slot[z] = 2;
        if (hasNormals) {
            slot[nx] = 3;
            slot[ny] = 4;
            slot[nz] = 5;
        }
        if (hasUvs) {
            slot[u] = 6;
            slot[v] = 7;
        }
        for (int i = 0; i < slot.length; i++) {
            if (slot[i] < 0) {
                skipped.add("vertex property '" + PlyHeader.shown(properties.get(i).name()) + "'");
            }
        }
        int count = (int) e.count();
        int capacity = Math.min(count, FIRST_CAPACITY);
        Growing.Doubles p = new Growing.Doubles();
        float[] n = hasNormals ? new float[3 * capacity] : null;
        float[] t = hasUvs ? new float[2 * capacity] : null;
        double[] values = new double[8];
        for (int i = 0; i < count; i++) {
            if (i == capacity) {
                capacity = (int) Math.min(count, 2L * capacity);
                n = n != null ? Arrays.copyOf(n, 3 * capacity) : null;
                t = t != null ? Arrays.copyOf(t, 2 * capacity) : null;
            }
            for (int k = 0; k < slot.length; k++) {
                PlyHeader.Property property = properties.get(k);
                try {
                    if (property.isList()) {
                        skipList(property, in);
                    } else if (slot[k] < 0) {
                        in.skip(property.type());
                    } else {
                        values[slot[k]] = in.real(property.type());
                    }
                } catch (EOFException end) {
                    throw new PlyException(at(e, i) + "the file ends early (truncated)");
                } catch (PlyInput.BadValue bad) {
                    throw new PlyException(at(e, i) + "property '" + PlyHeader.shown(property.name()) + "': " + bad.getMessage());
                }
            }
            for (int k = 0; k < 8; k++) {
                if (!Double.isFinite(values[k])) {
                    throw new PlyException(at(e, i) + "its " + (k < 3 ? "position" : k < 6 ? "normal" : "texture coordinate")
                                           + " is not finite (" + values[k] + ")");
                }
                if (k < 3 && !(Math.abs(values[k]) <= Triangle.MAX_COORDINATE)) {
                    throw new PlyException(at(e, i) + "its position coordinate " + values[k] + " is beyond "
                                           + Triangle.MAX_COORDINATE + " in size, more than a triangle holds");
                }
            }
            p.add(values[0]);
            p.add(values[1]);
            p.add(values[2]);
            if (n != null) {
                n[3 * i] = (float) values[3];
                n[3 * i + 1] = (float) values[4];
                n[3 * i + 2] = (float) values[5];
            }
            if (t != null) {
                t[2 * i] = (float) values[6];
                t[2 * i + 1] = (float) values[7];
            }
        }
        vertices = count;
        positions = p;
        normals = n;
        uvs = t;
    }

    private void readFaces(PlyHeader.Element e, PlyInput in, PlyHeader header) throws IOException, PlyException {
        if (facesRead) {
            // the triangles of one would replace the other's while the counts added up
            throw new PlyException(file + ": a second 'face' element");
        }
        facesRead = true;
        List<PlyHeader.Property> properties = e.properties();
        int list = -1;
        for (int k = 0; k < properties.size() && list < 0; k++) {
            String name = properties.get(k).name();
            if (properties.get(k).isList() && (name.equals("vertex_indices") || name.equals("vertex_index"))) {
                list = k;
            }
        }
        if (list < 0) {
            throw new PlyException(file + ": the face element needs a list property vertex_indices (or vertex_index)");
        }
        long known = vertexCount(header);
        for (int k = 0; k < properties.size(); k++) {
            if (k != list) {
                skipped.add("face property '" + PlyHeader.shown(properties.get(k).name()) + "'");
            }
        }
        int count = (int) e.count();
        triangles = new int[3 * Math.min(count, FIRST_CAPACITY)];
        int[] face = new int[16];
        for (int i = 0; i < count; i++) {
            int size = 0;
            for (int k = 0; k < properties.size(); k++) {
                PlyHeader.Property property = properties.get(k);
                try {
                    if (k != list) {
                        if (property.isList()) {
                            skipList(property, in);
                        } else {
                            in.skip(property.type());
                        }
                        continue;
                    }
                    long corners = in.integer(property.countType());
                    if (corners < 3 || corners > MAX_CORNERS) {
                        throw new PlyException(at(e, i) + "a face needs 3 to " + MAX_CORNERS + " vertices, got " + corners);
                    }
                    size = (int) corners;
                    if (face.length < size) {
                        face = new int[Math.max(size, 2 * face.length)];
                    }
                    for (int c = 0; c < size; c++) {
                        long index = in.integer(property.type());
                        if (index < 0 || index >= known) {
                            throw new PlyException(at(e, i) + "vertex index " + index + " is out of range (the file has "
                                                   + known + " vertices)");
                        }
                        face[c] = (int) index;
                    }
                } catch (EOFException end) {
                    throw new PlyException(at(e, i) + "the file ends early (truncated)");
                } catch (PlyInput.BadValue bad) {
                    throw new PlyException(at(e, i) + "property '" + PlyHeader.shown(property.name()) + "': " + bad.getMessage());
                }
            }
            addFan(face, size, e, i);
        }
    }

    /** The vertex count the header gives, whether the vertices come before the faces or after. */
    private long vertexCount(PlyHeader header) throws PlyException {
        for (PlyHeader.Element e : header.elements()) {
            if (e.name().equals("vertex")) {
                return e.count();
            }
        }
        throw new PlyException(file + ": no 'vertex' element");
    }

    /** Adds the face's fan of triangles (0, c, c + 1), growing the array as faces arrive. */
    private void addFan(int[] face, int size, PlyHeader.Element e, int i) throws PlyException {
        int added = 3 * (size - 2);
        if (corners > MAX_CORNER_INDICES - added) {
            throw new PlyException(at(e, i) + "more than " + MAX_CORNER_INDICES / 3 + " triangles do not fit one mesh");
        }
        if (corners + added > triangles.length) {
            long grown = Math.max((long) corners + added, 2L * triangles.length);
            triangles = Arrays.copyOf(triangles, (int) Math.min(grown, MAX_CORNER_INDICES));
        }
        for (int c = 1; c + 1 < size; c++) {
            triangles[corners++] = face[0];
            triangles[corners++] = face[c];
            triangles[corners++] = face[c + 1];
        }
        faces++;
        if (size > 3) {
            ngons++;
        }
    }

    private static void skipList(PlyHeader.Property property, PlyInput in) throws IOException {
        long n = in.integer(property.countType());
        if (n < 0) {
            throw new PlyInput.BadValue("a list of " + n + " values");
        }
        for (long j = 0; j < n; j++) {
            in.skip(property.type());
        }
    }

    private void skipElements(PlyHeader.Element e, PlyInput in) throws IOException, PlyException {
        for (long i = 0; i < e.count(); i++) {
            for (PlyHeader.Property property : e.properties()) {
                try {
                    if (property.isList()) {
                        skipList(property, in);
                    } else {
                        in.skip(property.type());
                    }
                } catch (EOFException end) {
                    throw new PlyException(at(e, i) + "the file ends early (truncated)");
                }
            }
        }
    }

    private String at(PlyHeader.Element e, long i) {
        return file + ": " + PlyHeader.shown(e.name()) + " " + i + " (of " + e.count() + ", counting from 0): ";
    }
}
