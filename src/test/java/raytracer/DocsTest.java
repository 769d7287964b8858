package raytracer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The documents say what the code is. In README.md and docs/*.md: every link to a file of the
 * repository reaches one; a link to a heading (#the-allocation-study) reaches a heading of that
 * name; a link to lines (#L12-L30) stays inside the file, and when it names a method
 * ([`World.hit`](...#L129-L144)) its first line declares or calls that method, so a line link that
 * drifted as the code moved fails here; and every method or field named in backticks as
 * {@code Class.member} exists, in the project's sources or, for a JDK class, by reflection.
 * Source comments may cite documents only by paths that exist.
 */
class DocsTest {
    private static final List<String> SOURCE_ROOTS = List.of("src/main/java", "src/test/java", "src/jmh/java", "src/exercises/java",
                                                             "src/solutions/java");
    /** [text](target), a target without spaces; images too. */
    private static final Pattern LINK = Pattern.compile("\\[([^\\]]*)\\]\\(([^)\\s]+)\\)");
    private static final Pattern LINES = Pattern.compile("L(\\d+)(?:-L(\\d+))?");
    /** `Class.member` or `package.Class.member`, with optional arguments: `Math.max(h, 0)`. */
    private static final Pattern MEMBER = Pattern.compile("`((?:[a-z][a-z0-9]*\\.)*)((?:[A-Z]\\w*\\.)*[A-Z]\\w*)\\.([a-zA-Z_]\\w*)(?:\\([^`]*\\))?`");
    /** The method a link's text names: the last identifier in backticks. */
    private static final Pattern NAMED_METHOD = Pattern.compile("`(?:[\\w.]*\\.)?([a-z]\\w*)(?:\\([^`]*\\))?`");

    private final Map<String, List<Path>> sourcesByName = new HashMap<>();

    private static List<Path> documents() throws IOException {
        List<Path> docs = new ArrayList<>(List.of(Path.of("README.md")));
        try (Stream<Path> files = Files.list(Path.of("docs"))) {
            files.filter(f -> f.toString().endsWith(".md")).sorted().forEach(docs::add);
        }
        return docs;
    }

    /** The text outside fenced code blocks, line for line (fenced lines blanked), so line numbers stay right. */
    private static List<String> prose(Path doc) throws IOException {
        List<String> lines = new ArrayList<>();
        boolean fenced = false;
        for (String line : Files.readAllLines(doc)) {
            if (line.strip().startsWith("```")) {
                fenced = !fenced;
                lines.add("");
            } else {
                lines.add(fenced ? "" : line);
            }
        }
        return lines;
    }

    @Test
    void linksReachTheirFilesHeadingsAndLines() throws IOException {
        List<String> broken = new ArrayList<>();
        int lineLinks = 0;
        for (Path doc : documents()) {
            List<String> lines = prose(doc);
            for (int n = 0; n < lines.size(); n++) {
                Matcher m = LINK.matcher(lines.get(n));
                while (m.find()) {
                    String target = m.group(2);
                    if (target.matches("[a-z]+:.*")) {
                        continue; // https:, mailto:
                    }
                    String where = doc + ":" + (n + 1) + ": [" + m.group(1) + "](" + target + ")";
                    int hash = target.indexOf('#');
                    String file = hash < 0 ? target : target.substring(0, hash);
                    String anchor = hash < 0 ? null : target.substring(hash + 1);
                    Path resolved = file.isEmpty() ? doc : doc.getParent() == null ? Path.of(file) : doc.getParent().resolve(file);
                    resolved = resolved.normalize();
                    if (!Files.exists(resolved)) {
                        broken.add(where + ": no file " + resolved);
                        continue;
                    }
                    if (anchor == null) {
                        continue;
                    }
                    Matcher lineAnchor = LINES.matcher(anchor);
                    if (lineAnchor.matches()) {
                        lineLinks++;
                        String problem = lineProblem(resolved, lineAnchor, m.group(1));
                        if (problem != null) {
                            broken.add(where + ": " + problem);
                        }
                    } else if (resolved.toString().endsWith(".md") && !headings(resolved).contains(anchor)) {
                        broken.add(where + ": no heading '" + anchor + "' in " + resolved);
                    }
                }
            }
        }
        assertTrue(lineLinks >= 30, "docs/ray-life.md links each step to its lines; found " + lineLinks + " line links");
        assertEquals(List.of(), broken, "links that lead nowhere");
    }

    /** Why a link to lines {@code anchor} of {@code file} is wrong, or null. */
    private static String lineProblem(Path file, Matcher anchor, String text) throws IOException {
        List<String> lines = Files.readAllLines(file);
        int first = Integer.parseInt(anchor.group(1));
        int last = anchor.group(2) == null ? first : Integer.parseInt(anchor.group(2));
        if (first < 1 || last < first || last > lines.size()) {
            return "lines " + first + "-" + last + " of a file of " + lines.size();
        }
        Matcher named = NAMED_METHOD.matcher(text);
        String method = null;
        while (named.find()) {
            method = named.group(1);
        }
        if (method != null && !Pattern.compile("\\b" + method + "\\s*\\(").matcher(lines.get(first - 1)).find()) {
            return "line " + first + " does not name " + method + "(: '" + lines.get(first - 1).strip() + "'";
        }
        return null;
    }

    /** GitHub's anchors of a Markdown file's headings: lower case, punctuation dropped, spaces as hyphens, repeats numbered. */
    static List<String> headings(Path doc) throws IOException {
        List<String> anchors = new ArrayList<>();
        Map<String, Integer> seen = new HashMap<>();
        for (String line : prose(doc)) {
            if (!line.startsWith("#")) {
                continue;
            }
            String slug = line.replaceFirst("^#+\\s*", "").strip().toLowerCase(Locale.ROOT)
                .replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-');
            int count = seen.merge(slug, 1, Integer::sum);
            anchors.add(count == 1 ? slug : slug + "-" + (count - 1));
        }
        return anchors;
    }

    @Test
    void everyMethodNamedInTheDocsExists() throws IOException {
        List<String> missing = new ArrayList<>();
        for (Path doc : documents()) {
            List<String> lines = prose(doc);
            for (int n = 0; n < lines.size(); n++) {
                Matcher m = MEMBER.matcher(lines.get(n));
                while (m.find()) {
                    String problem = memberProblem(m.group(2), m.group(3));
                    if (problem != null) {
                        missing.add(doc + ":" + (n + 1) + ": " + m.group() + ": " + problem);
                    }
                }
            }
        }
        assertEquals(List.of(), missing, "methods and fields the documents name but the code does not have");
    }

    /** Why {@code type.member} (type possibly nested: Outer.Inner) does not exist, or null. */
    private String memberProblem(String type, String member) throws IOException {
        String[] parts = type.split("\\.");
        String simple = parts[parts.length - 1];
        List<Path> files = sources(parts[0]);
        if (files.isEmpty()) {
            return jdkProblem(type, member);
        }
        for (Path file : files) {
            String text = Files.readString(file);
            if (parts.length > 1 && !Pattern.compile("\\b(class|record|enum|interface)\\s+" + simple + "\\b").matcher(text).find()) {
                continue;
            }
            // members of a top-level type are indented 4 spaces, of a nested one 8: a deeper match is a local variable
            String indent = "(?m)^ {" + 4 * parts.length + "}";
            boolean declared = Pattern.compile(indent + "(?:[\\w@<>\\[\\],.?]+ )*[\\w<>\\[\\],.?]+ " + member + "\\s*[(=;]").matcher(text).find()
                               || Pattern.compile(indent + member + "\\b").matcher(text).find()     // an enum constant
                               || Pattern.compile("\\b(class|record|enum|interface)\\s+" + member + "\\b").matcher(text).find()
                               || Pattern.compile("record\\s+" + simple + "\\s*\\([^)]*\\b" + member + "\\s*[,)]").matcher(text).find();
            if (declared) {
                return null;
            }
        }
        return "no " + member + " in " + files;
    }

    /** The project's source files named {@code simple}.java, or holding a type of that name. */
    private List<Path> sources(String simple) throws IOException {
        if (sourcesByName.isEmpty()) {
            for (String root : SOURCE_ROOTS) {
                try (Stream<Path> files = Files.walk(Path.of(root))) {
                    files.filter(f -> f.toString().endsWith(".java")).forEach(f -> {
                        try {
                            Matcher types = Pattern.compile("\\b(?:class|record|enum|interface)\\s+([A-Z]\\w*)").matcher(Files.readString(f));
                            while (types.find()) {
                                sourcesByName.computeIfAbsent(types.group(1), k -> new ArrayList<>()).add(f);
                            }
                        } catch (IOException e) {
                            throw new UncheckedIOException(e);
                        }
                    });
                }
            }
        }
        return sourcesByName.getOrDefault(simple, List.of());
    }

    /** For a class of the JDK (Math, BufferedImage): why it has no such member, or null; a class found nowhere is a problem too. */
    private static String jdkProblem(String type, String member) {
        for (String pkg : List.of("java.lang.", "java.util.", "java.awt.image.", "java.nio.file.", "java.io.")) {
            Class<?> c;
            try {
                c = Class.forName(pkg + type);
            } catch (ClassNotFoundException e) {
                continue;
            }
            for (Method method : c.getMethods()) {
                if (method.getName().equals(member)) {
                    return null;
                }
            }
            for (Field field : c.getFields()) {
                if (field.getName().equals(member)) {
                    return null;
                }
            }
            return "the JDK's " + c.getName() + " has no " + member;
        }
        return "no class " + type + " in the sources or the JDK";
    }

    @Test
    void sourceCommentsCiteDocumentsThatExist() throws IOException {
        Pattern cited = Pattern.compile("docs/[\\w./-]+\\.md");
        List<String> broken = new ArrayList<>();
        for (String root : SOURCE_ROOTS) {
            try (Stream<Path> files = Files.walk(Path.of(root))) {
                for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
                    String text = Files.readString(f);
                    Matcher m = cited.matcher(text);
                    while (m.find()) {
                        if (!Files.exists(Path.of(m.group()))) {
                            broken.add(f + ": " + m.group());
                        }
                    }
                    // spelt in two pieces, so that this file does not cite it
                    if (text.contains("SPEC" + " section")) {
                        broken.add(f + ": cites a SPEC file, a document the repository does not have (cite the report's section)");
                    }
                }
            }
        }
        assertEquals(List.of(), broken, "documents cited by source comments");
    }
}
