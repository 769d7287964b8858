package raytracer.io.obj;

import java.util.regex.Matcher;
import raytracer.shapes.Triangle;

/**
 * The parse of a chunk that holds nothing but the commonest lines, "v x y z" and "f a b c" with
 * positive indices (besides blanks and comments): the whole of a scanned mesh. It needs no state
 * from the lines before it, so chunks are parsed in parallel and appended in order. Any other line
 * makes the chunk {@link #general}: it is then parsed line by line in order, as is every error, so
 * messages and relative indices come out as from a serial read. A parse writes into a
 * {@link Scratch} that the pipeline hands from chunk to chunk, so that parsing a file allocates
 * nothing per chunk once the first few are in flight.
 */
final class PlainChunk {
    /** The chunk's result when a line needs the general parser. */
    static final PlainChunk GENERAL = new PlainChunk(true, null, 0, null, 0, 0, 0);

    /** The arrays a parse writes into, reused by the next chunk once this one is merged. */
    static final class Scratch {
        // a chunk of a scanned mesh is about 1/3 vertices and 2/3 triangles, of some 25 to 40 bytes a line
        final Buffers.Doubles positions = new Buffers.Doubles(LineChunks.CHUNK / 32);
        final Buffers.Ints corners = new Buffers.Ints(LineChunks.CHUNK / 16);
    }

    /** True when a line needs the general parser. */
    final boolean general;
    final double[] positions;
    final int positionCount;
    /** 0-based vertex indices, three a triangle. */
    final int[] corners;
    final int cornerCount;
    /** Lines in the chunk: '\n', '\r' and "\r\n" each end one, as in BufferedReader.readLine. */
    final int lines;
    /**
     * The largest (index - vertices defined earlier in the chunk) over all corners: the faces are
     * in range when the vertices before the chunk are at least this many.
     */
    final int excess;

    private PlainChunk(boolean general, double[] positions, int positionCount, int[] corners, int cornerCount,
                       int lines, int excess) {
        this.general = general;
        this.positions = positions;
        this.positionCount = positionCount;
        this.corners = corners;
        this.cornerCount = cornerCount;
        this.lines = lines;
        this.excess = excess;
    }

    /** The plain parse of {@code text} into {@code scratch} (whose values it replaces), or {@link #GENERAL}. */
    static PlainChunk parse(CharSequence text, Scratch scratch) {
        try {
            return parsePlain(text, scratch);
        } catch (RuntimeException e) {
            return GENERAL; // whatever the fast path cannot take, the line-by-line parse reports at its line
        }
    }

    private static PlainChunk parsePlain(CharSequence text, Scratch scratch) {
        Parser parser = new Parser(text, scratch);
        int lines = 0;
        int start = 0;
        int length = text.length();
        // a '\r' alone ends a line too; indexOf is an intrinsic, so the next '\n' and the next '\r'
        // are each looked up ahead and again only once passed: a text without one of them (old Mac
        // or Unix line ends) is searched to its end once, not once a line
        int lf = indexOrLength(text, '\n', 0);
        int cr = indexOrLength(text, '\r', 0);
        while (start < length) {
            int end = Math.min(lf, cr);
            lines++;
            if (!parser.line(start, end)) {
                return GENERAL;
            }
            start = end < length - 1 && text.charAt(end) == '\r' && text.charAt(end + 1) == '\n' ? end + 2 : end + 1;
            if (lf < start) {
                lf = indexOrLength(text, '\n', start);
            }
            if (cr < start) {
                cr = indexOrLength(text, '\r', start);
            }
        }
        return new PlainChunk(false, parser.positions.data, parser.positions.size, parser.corners.data,
                              parser.corners.size, lines, parser.excess);
    }

    static int indexOrLength(CharSequence text, char c, int from) {
        int i = text instanceof ByteChars bytes ? bytes.indexOf(c, from) : ((String) text).indexOf(c, from);
        return i < 0 ? text.length() : i;
    }

    /**
     * One line at a time, each in a small method: the JIT compiles a method called many times long
     * before it replaces a loop running inside one call (one 2x slower parse, cold, in one method).
     */
    private static final class Parser {
        private final CharSequence text;
        private final Matcher vertex;
        private final Matcher triangle;
        private final Matcher keyword;
        final Buffers.Doubles positions;
        final Buffers.Ints corners;
        int excess = Integer.MIN_VALUE;

        Parser(CharSequence text, Scratch scratch) {
            this.text = text;
            vertex = ObjPatterns.VERTEX_PLAIN.matcher(text);
            triangle = ObjPatterns.TRIANGLE_PLAIN.matcher(text);
            keyword = ObjPatterns.KEYWORD.matcher(text);
            positions = scratch.positions;
            corners = scratch.corners;
            positions.size = 0;
            corners.size = 0;
        }

        /** Parses the line [start, end); false when it needs the general parser. */
        boolean line(int start, int end) {
            if (end > start && text.charAt(end - 1) == '\\') {
                return false; // continued
            }
            if (vertex.region(start, end).matches()) {
                return vertex();
            }
            if (triangle.region(start, end).matches()) {
                return triangle();
            }
            return !keyword.region(start, end).lookingAt(); // blank or comment
        }

        private boolean vertex() {
            for (int g = 1; g <= 3; g++) {
                double v = Numbers.parseDouble(text, vertex.start(g), vertex.end(g));
                if (!Double.isFinite(v) || Math.abs(v) > Triangle.MAX_COORDINATE) {
                    return false; // the general parser says which line and why
                }
                positions.add(v);
            }
            return true;
        }

        private boolean triangle() {
            for (int g = 1; g <= 3; g++) {
                int index = Numbers.parseInt(text, triangle.start(g), triangle.end(g));
                if (index == 0) {
                    return false;
                }
                corners.add(index - 1);
                excess = Math.max(excess, index - positions.size / 3);
            }
            return true;
        }
    }
}
