package raytracer.io.scene;

import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.OptionalInt;
import java.util.Set;
import org.yaml.snakeyaml.LoaderOptions;
import org.yaml.snakeyaml.composer.Composer;
import org.yaml.snakeyaml.error.MarkedYAMLException;
import org.yaml.snakeyaml.error.YAMLException;
import org.yaml.snakeyaml.nodes.Node;
import org.yaml.snakeyaml.parser.ParserImpl;
import org.yaml.snakeyaml.resolver.Resolver;
import raytracer.cache.MeshCache;
import raytracer.core.World;

/**
 * Reads a scene file into a {@link LoadedScene}: the {@link World}, the render settings the file
 * gives and the report of the loading; of an animation, its first frame ({@link SceneFile} loads
 * any frame). Every problem becomes a {@link SceneException} naming file, line and column.
 */
public final class SceneLoader {
    static final Set<String> SECTIONS =
        Set.of("image", "tracer", "pass", "background", "environment", "camera", "ambient", "materials", "lights", "objects");

    /**
     * The most characters (Unicode code points) a scene file may hold. SnakeYAML's default, 3 MiB,
     * refused a generated scene of 66,576 spheres (4.9 MB). 64 MiB holds 900,000 spheres written one
     * a line, which took 33 s and 3.4 GiB of heap to load (2 shared cores): past that, a mesh file is
     * the better form.
     */
    static final int MAX_CHARACTERS = 64 << 20;

    /** The sections of a scene file: {@link #SECTIONS} and the animation, which {@link SceneFile} reads. */
    static final Set<String> FILE_SECTIONS = union(SECTIONS, "animation");

    private SceneLoader() {
    }

    private static Set<String> union(Set<String> names, String name) {
        return union(names, Set.of(name));
    }

    private static Set<String> union(Set<String> a, Set<String> b) {
        Set<String> all = new java.util.HashSet<>(a);
        all.addAll(b);
        return Set.copyOf(all);
    }

    /** Reads a scene file; its meshes are parsed, not cached. */
    public static LoadedScene load(Path file) throws SceneException {
        return load(file, OptionalInt.empty());
    }

    /**
     * As {@link #load(Path)}, with the meshes read from {@code cache} when it has them and written
     * to it when it does not (null: no cache).
     */
    public static LoadedScene load(Path file, MeshCache cache) throws SceneException {
        return withInput(load(source(file), text(file), OptionalInt.empty(), cache), file);
    }

    /**
     * As {@link #load(Path)}; with {@code areaLightSamples} every area light takes that many samples
     * per shaded point instead of its {@code samples} key (the convergence benchmark's override).
     */
    public static LoadedScene load(Path file, OptionalInt areaLightSamples) throws SceneException {
        return load(file, areaLightSamples, 0);
    }

    /** As {@link #load(Path, OptionalInt)}, frame {@code frame} of an animated scene (0 to its frames - 1). */
    public static LoadedScene load(Path file, OptionalInt areaLightSamples, int frame) throws SceneException {
        return withInput(SceneFile.of(source(file), text(file), areaLightSamples, null).load(frame), file);
    }

    private static LoadedScene withInput(LoadedScene loaded, Path file) {
        loaded.report().addInput(file);
        return loaded;
    }

    static Source source(Path file) {
        return new Source(file.toString(), file.toAbsolutePath().getParent());
    }

    /**
     * The file's text, or a SceneException saying why it cannot be read. The file may be a pipe (a
     * scene written by another program): it is read up to {@link #MAX_CHARACTERS} and refused past
     * that, so a file that never ends ({@code /dev/zero}) stops there rather than filling the heap.
     */
    static String text(Path file) throws SceneException {
        if (Files.isDirectory(file)) {
            throw new SceneException("cannot read scene file " + file + ": it is a directory");
        }
        CharsetDecoder utf8 = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
            .onUnmappableCharacter(CodingErrorAction.REPORT);
        try (Reader in = new InputStreamReader(Files.newInputStream(file), utf8)) {
            StringBuilder text = new StringBuilder();
            char[] buffer = new char[1 << 16];
            long codePoints = 0;
            for (int n; (n = in.read(buffer)) > 0; ) {
                text.append(buffer, 0, n);
                for (int i = 0; i < n; i++) {
                    // a code point is a char that is not the second half of a surrogate pair
                    codePoints += Character.isLowSurrogate(buffer[i]) ? 0 : 1;
                }
                if (codePoints > MAX_CHARACTERS) {
                    throw tooLong(file.toString());
                }
            }
            return text.toString();
        } catch (NoSuchFileException e) {
            throw new SceneException("cannot read scene file " + file + ": no such file");
        } catch (AccessDeniedException e) {
            throw new SceneException("cannot read scene file " + file + ": permission denied");
        } catch (CharacterCodingException e) {
            throw new SceneException("cannot read scene file " + file + ": not UTF-8 text");
        } catch (IOException e) {
            throw new SceneException("cannot read scene file " + file + ": " + e.getMessage(), e);
        }
    }

    private static SceneException tooLong(String name) {
        return new SceneException(name + ": the scene file has more than the " + MAX_CHARACTERS + " characters a scene may hold "
                                  + "(put large meshes in OBJ files)");
    }

    /** Reads scene text; {@code sourceName} is used in messages, relative paths start at the working directory. */
    public static LoadedScene load(String sourceName, String text) throws SceneException {
        return load(new Source(sourceName, null), text, OptionalInt.empty(), null);
    }

    static LoadedScene load(Source source, String text, OptionalInt areaLightSamples, MeshCache cache) throws SceneException {
        return SceneFile.of(source, text, areaLightSamples, cache).load(0);
    }

    /** The YAML node tree of a scene's text; an empty text is an error. */
    static Node root(Source source, String text) throws SceneException {
        Node root = compose(source, text);
        if (root == null) {
            throw new SceneException(source.name() + ": the scene file is empty");
        }
        return root;
    }

    /** The YAML node tree of the text; size, characters and syntax checked, in that order. */
    private static Node compose(Source source, String text) throws SceneException {
        if (text.codePointCount(0, text.length()) > MAX_CHARACTERS) {
            throw tooLong(source.name());
        }
        int bad = SceneText.firstUnprintable(text);
        if (bad >= 0) {
            SceneText at = new SceneText(source.name(), text);
            at.forward(text.codePointCount(0, bad));
            throw source.error(at.getMark(),
                               String.format("character U+%04X is not allowed in a YAML file", text.codePointAt(bad)));
        }
        LoaderOptions options = new LoaderOptions();
        options.setAllowDuplicateKeys(false);
        options.setCodePointLimit(MAX_CHARACTERS);
        SceneText reader = new SceneText(source.name(), text);
        try {
            return new Composer(new ParserImpl(reader, options), new Resolver(), options).getSingleNode();
        } catch (MarkedYAMLException e) {
            String problem = e.getProblem() != null ? e.getProblem() : e.getMessage();
            throw (e.getProblemMark() != null ? source.error(e.getProblemMark(), "syntax error: " + problem)
                                              : new SceneException(source.name() + ": syntax error: " + problem));
        } catch (YAMLException e) {
            // SnakeYAML's limits (nesting, aliases) carry no mark: where the reader stopped is where the limit was passed
            throw source.error(reader.getMark(), limit(e.getMessage(), options));
        }
    }

    /** SnakeYAML's message of a limit passed, in words that say what to change. */
    private static String limit(String message, LoaderOptions options) {
        String m = message == null ? "" : message.replace('\n', ' ');
        if (m.startsWith("Nesting Depth exceeded")) {
            return "lists and mappings nested deeper than " + options.getNestingDepthLimit() + " levels";
        }
        if (m.startsWith("Number of aliases")) {
            return "more than " + options.getMaxAliasesForCollections() + " aliases (*name) of lists or mappings; a scene "
                   + "this repetitive is refused rather than expanded";
        }
        return "syntax error: " + m;
    }
}
