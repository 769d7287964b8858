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
import raytracer.shapes.mesh.ParsedMesh;
import raytracer.shapes.mesh.SmoothNormals;

/**
 * Loads a PLY file (optionally gzip-compressed, {@code .ply.gz}) into one {@link ParsedMesh}: the
 * {@code vertex} element's positions, normals and texture coordinates ({@link PlyVertices}) and the
 * {@code face} element's index lists, fan-triangulated ({@link PlyFaces}), the elements in any
 * order. Other properties (colours, a scanner's confidence) and elements are read past, named in
 * one warning; so are header lines of unknown keywords ({@link PlyHeader}), faces of fewer than
 * three corners, and data after the header's last element, which plyfile and trimesh leave unread
 * too. A malformed header or body is one error naming the file and the header line, or the
 * element, its row and (ASCII) the line.
 */
public final class PlyLoader {
    private final String file;
    private final List<String> warnings = new ArrayList<>();
    private final Set<String> skipped = new LinkedHashSet<>();
    private final List<String> otherElements = new ArrayList<>();
    private PlyVertices vertices;
    private PlyFaces faces;

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
        PlyBody body;
        try (InputStream raw = Files.newInputStream(path);
             InputStream in = new BufferedInputStream(file.endsWith(".gz") ? new GZIPInputStream(raw, 1 << 16) : raw, 1 << 16)) {
            PlyHeader header = PlyHeader.read(in, file);
            warnings.addAll(header.warnings());
            body = new PlyBody(file, header, PlyInput.of(header.format(), in, header.lines() + 1));
            for (PlyHeader.Element e : header.elements()) {
                switch (e.name()) {
                    case "vertex" -> readVertices(e, body);
                    case "face" -> readFaces(e, body, header);
                    default -> {
                        skipped.add("element '" + PlyHeader.shown(e.name()) + "'");
                        otherElements.add("element '" + PlyHeader.shown(e.name()) + "'");
                        body.skipAll(e);
                    }
                }
            }
            if (body.in.hasMore()) {
                PlyHeader.Element last = header.elements().isEmpty() ? null : header.elements().get(header.elements().size() - 1);
                int line = body.in.line();
                warnings.add(file + (line > 0 ? ":" + line : "") + ": the body goes on after the last element the header declares"
                             + (last == null ? "" : " ('" + PlyHeader.shown(last.name()) + "')") + "; the rest is not read");
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
        if (vertices == null) {
            throw body.missing("no 'vertex' element");
        }
        if (faces == null || faces.faces == 0) {
            long none = faces == null ? 0 : faces.degenerate;
            // a 'tristrips' element (tinyply's elephant.ply) is one of these: plyfile and trimesh read no faces from it either
            String others = otherElements.isEmpty() ? "" : "; read past: " + String.join(", ", otherElements);
            throw body.missing("no faces (a PLY mesh needs a 'face' element with vertex_indices"
                               + (none == 0 ? "" : none == 1 ? "; its 1 face has fewer than 3 corners"
                                                             : "; its " + none + " faces all have fewer than 3 corners")
                               + others + ")");
        }
        if (faces.degenerate > 0) {
            warnings.add(faces.firstDegenerate + " (" + faces.degenerate + (faces.degenerate == 1 ? " face" : " faces")
                         + " of fewer than 3 corners skipped)");
        }
        if (!skipped.isEmpty()) {
            warnings.add(file + ": read past " + String.join(", ", skipped) + " (not used)");
        }
        int[] t = Arrays.copyOf(faces.triangles, faces.corners);
        float[] n = vertices.normals != null ? vertices.normals
                    : smoothNormals ? SmoothNormals.angleWeighted(vertices.positions, t) : null;
        return new PlyModel(new ParsedMesh(vertices.positions, n, vertices.uvs, t, null), List.copyOf(warnings), faces.faces,
                            faces.ngons);
    }

    private void readVertices(PlyHeader.Element e, PlyBody body) throws IOException, PlyException {
        if (vertices != null) {
            throw body.error("a second 'vertex' element");
        }
        vertices = PlyVertices.read(e, body, skipped);
    }

    private void readFaces(PlyHeader.Element e, PlyBody body, PlyHeader header) throws IOException, PlyException {
        if (faces != null) {
            // the triangles of one would replace the other's while the counts added up
            throw body.error("a second 'face' element");
        }
        faces = PlyFaces.read(e, body, vertexCount(header, body), skipped);
    }

    /** The vertex count the header gives, whether the vertices come before the faces or after. */
    private static long vertexCount(PlyHeader header, PlyBody body) throws PlyException {
        for (PlyHeader.Element e : header.elements()) {
            if (e.name().equals("vertex")) {
                return e.count();
            }
        }
        throw body.missing("no 'vertex' element");
    }
}
