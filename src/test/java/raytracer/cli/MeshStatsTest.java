package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** --stats names each mesh with its triangles, vertices and n-gons, the first things checked after a load. */
class MeshStatsTest {
    @TempDir
    Path dir;

    @Test
    void statsCountEachMesh() throws IOException {
        // a quad, a pentagon and a triangle: 2 + 3 + 1 triangles over 5 positions; a second mesh of one triangle
        Files.writeString(dir.resolve("shapes.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\n"
                                                     + "f 1 2 3 4\nf 1 2 3 5 4\nf 1 2 3\n");
        Files.writeString(dir.resolve("one.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n");
        Path scene = dir.resolve("s.yaml");
        Files.writeString(scene, """
            image: {width: 8, height: 8, samples: 1}
            camera: {type: pinhole, eye: [0, 0, 5], look-at: [0, 0, 0], fov: 40}
            lights:
              - {type: point, position: [1, 1, 5], intensity: 1}
            objects:
              - {type: mesh, file: shapes.obj}
              - {type: mesh, file: one.obj}
            """);
        StringWriter err = new StringWriter();
        int code = RenderCommand.run(new PrintWriter(err, true), scene.toString(), "-o", dir.resolve("s.png").toString(), "--stats",
                                      "--no-cache");
        assertEquals(0, code, err.toString());
        List<String> meshes = err.toString().lines().filter(l -> l.startsWith("stats: mesh ") && l.contains(" triangle")).toList();
        assertEquals(List.of(
            "stats: mesh shapes.obj: 6 triangles, 5 vertices; 2 of 3 faces had more than 3 corners (fan-triangulated)",
            "stats: mesh one.obj: 1 triangle, 3 vertices; 0 of 1 face had more than 3 corners (fan-triangulated)"), meshes);
        assertTrue(err.toString().indexOf("stats: load scene") < err.toString().indexOf("stats: mesh "), err.toString());
    }
}
