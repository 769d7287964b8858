package raytracer.io.obj;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntFunction;
import java.util.regex.Pattern;

/**
 * The warnings about one OBJ or MTL file. Each kind of oddity is reported once, at its first line,
 * with how often it occurred, so a file of a million odd lines gives one line of warning. Nothing
 * of a line is echoed but a keyword that looks like one: a path given by mistake
 * ({@code mtllib ../../etc/passwd}) must not copy someone else's file into the output.
 */
final class FileWarnings {
    /** Unknown keywords named one by one; past these a file is most likely not OBJ or MTL at all. */
    static final int KEYWORDS_NAMED = 8;
    /** What a keyword of OBJ or MTL looks like (v, vt, map_Kd, Tr, ...); anything else is never shown. */
    private static final Pattern KEYWORD = Pattern.compile("[A-Za-z_][A-Za-z0-9_]{0,31}");

    private final String file;
    private final List<String> out;
    /** Per kind: where its warning sits in {@link #out}, and how to word it for a count. */
    private final Map<String, Tally> tallies = new HashMap<>();
    private int keywordsNamed;

    private static final class Tally {
        final int index;
        final String where;
        final IntFunction<String> message;
        int count;

        Tally(int index, String where, IntFunction<String> message) {
            this.index = index;
            this.where = where;
            this.message = message;
        }
    }

    FileWarnings(String file, List<String> out) {
        this.file = file;
        this.out = out;
    }

    /** A warning of its own, at {@code line}. */
    void add(int line, String message) {
        out.add(file + ":" + line + ": " + message);
    }

    /**
     * One more occurrence of {@code kind}; the first, at {@code line}, places the warning, worded at
     * {@link #finish} by {@code message} for the final count.
     */
    void tally(String kind, int line, IntFunction<String> message) {
        Tally t = tallies.get(kind);
        if (t == null) {
            t = new Tally(out.size(), file + ":" + line + ": ", message);
            tallies.put(kind, t);
            out.add(null); // worded at finish, in the place of its first line
        }
        t.count++;
    }

    void unknownKeyword(int line, String keyword) {
        if (!KEYWORD.matcher(keyword).matches()) {
            tally("", line, n -> (n == 1 ? "a line that does not" : n + " lines that do not")
                                 + " begin with a keyword ignored");
            return;
        }
        String kind = "keyword " + keyword;
        if (!tallies.containsKey(kind)) {
            if (keywordsNamed == KEYWORDS_NAMED) {
                tally("more keywords", line, n -> "more unknown keywords ignored (" + lines(n) + ")");
                return;
            }
            keywordsNamed++;
        }
        tally(kind, line, n -> "unknown keyword '" + keyword + "' ignored (" + lines(n) + ")");
    }

    /** Words the counted warnings; call once, after the last line. */
    void finish() {
        for (Tally t : tallies.values()) {
            out.set(t.index, t.where + t.message.apply(t.count));
        }
    }

    private static String lines(int n) {
        return n == 1 ? "1 line" : n + " lines";
    }

    /** Text of a file for a message: at most {@code max} characters, control characters as '?'. */
    static String shown(String text, int max) {
        String s = text.strip();
        StringBuilder b = new StringBuilder(Math.min(s.length(), max) + 3);
        for (int i = 0; i < s.length() && i < max; i++) {
            char c = s.charAt(i);
            // control and format characters (a bidirectional override among them) could garble the terminal
            b.append(Character.isISOControl(c) || Character.getType(c) == Character.FORMAT || c == '\uFFFD' ? '?' : c);
        }
        return s.length() > max ? b.append("...").toString() : b.toString();
    }
}
