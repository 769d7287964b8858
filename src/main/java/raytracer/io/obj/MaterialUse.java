package raytracer.io.obj;

import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import raytracer.shapes.mesh.Growing;

/**
 * The materials of an OBJ file: what its {@code mtllib} libraries define, which one {@code usemtl}
 * made current, and a material id per triangle once any is used. A name no library defines, and
 * the faces before the first {@code usemtl}, get a grey fallback.
 */
final class MaterialUse {
    private final Path folder;
    private final String objName;
    private final List<String> warnings;
    private final List<ObjMaterial> materials = new ArrayList<>();
    private final Map<String, Integer> index = new HashMap<>();
    private final Map<String, ObjMaterial> library = new HashMap<>();
    private final List<Path> libraries = new ArrayList<>();
    private final Growing.Ints ids = new Growing.Ints();
    private int current = -1;
    private boolean used;

    MaterialUse(Path objFile, List<String> warnings) {
        this.folder = objFile.toAbsolutePath().getParent();
        this.objName = objFile.toString();
        this.warnings = warnings;
    }

    /**
     * {@code mtllib} names one or more libraries, separated by spaces; a whole argument that names
     * a file is one name with spaces (as some exporters write it).
     */
    void loadLibraries(String argument, int line) throws ObjException {
        String whole = Arguments.path(Arguments.withoutComment(argument));
        try {
            if (!whole.isEmpty() && Files.isRegularFile(folder.resolve(whole))) {
                load(whole, line);
                return;
            }
        } catch (InvalidPathException e) {
            // not one name; its parts are tried below
        }
        for (String lib : whole.split("\\s+")) {
            if (!lib.isEmpty()) {
                load(lib, line);
            }
        }
    }

    /** Loads one library: one that cannot be read is a warning, a value out of range in it an error. */
    private void load(String lib, int line) throws ObjException {
        Path file;
        Decoding.Text text;
        try {
            file = folder.resolve(lib).normalize();
            text = MtlLoader.read(file);
        } catch (ObjException e) {
            warnings.add(objName + ":" + line + ": " + e.getMessage() + "; its materials fall back to grey");
            return;
        } catch (InvalidPathException e) {
            warnings.add(objName + ":" + line + ": material library '" + FileWarnings.shown(lib, 60)
                         + "' is not a valid path; its materials fall back to grey");
            return;
        }
        library.putAll(MtlLoader.parse(file, text, warnings));
        libraries.add(file);
    }

    /** {@code usemtl name} after {@code triangles} triangles. */
    void use(String name, int line, int triangles) {
        if (!used) {
            used = true;
            if (triangles > 0) {
                current = id("(default)", line);
                ids.fill(current, triangles);
            }
        }
        current = id(name, line);
    }

    /** Notes the current material for {@code count} more triangles. */
    void addTriangles(int count) {
        if (used) {
            ids.fill(current, count);
        }
    }

    private int id(String name, int line) {
        Integer known = index.get(name);
        if (known != null) {
            return known;
        }
        ObjMaterial m = library.get(name);
        if (m == null) {
            if (!name.equals("(default)")) {
                warnings.add(objName + ":" + line + ": material '" + FileWarnings.shown(name, 60)
                             + "' is not defined in any mtllib; using grey");
            }
            m = ObjMaterial.fallback(name);
        }
        materials.add(m);
        index.put(name, materials.size() - 1);
        return materials.size() - 1;
    }

    List<ObjMaterial> materials() {
        return List.copyOf(materials);
    }

    /** The MTL files read, in the order read. */
    List<Path> libraries() {
        return List.copyOf(libraries);
    }

    /** A material id per triangle, or null when no face named one. */
    int[] ids() {
        return used ? ids.toArray() : null;
    }
}
