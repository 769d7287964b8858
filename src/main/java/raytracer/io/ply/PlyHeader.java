package raytracer.io.ply;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;

/**
 * A PLY header: the format and the elements, each with its count and typed properties, read from
 * the first line {@code ply} to {@code end_header}. Comments, obj_info and blank lines are passed
 * over anywhere. A line of another keyword is skipped with a warning: Blender 2.47 wrote its
 * banner as a line of free text; trimesh reads past such lines and tinyply reports them and reads
 * on (plyfile refuses them).
 *
 * @param lines the header's lines, end_header's included: the body's first line is the next
 * @param skipped the first line skipped, as "header line N: unknown keyword 'K'", or null
 */
record PlyHeader(Format format, List<Element> elements, int lines, List<String> warnings, String skipped) {
    /** What a keyword looks like; any other text of a skipped line is not shown. */
    private static final Pattern KEYWORD = Pattern.compile("[A-Za-z_][A-Za-z0-9_]{0,31}");

    /** A header longer than this is not a PLY header (the Stanford files' are a few hundred bytes). */
    static final int MAX_BYTES = 1 << 20;

    enum Format { ASCII, BINARY_LITTLE_ENDIAN, BINARY_BIG_ENDIAN }

    /** A property: a scalar of {@code type}, or, when {@code countType} is not null, a list of them preceded by its count. */
    record Property(String name, PlyType type, PlyType countType) {
        boolean isList() {
            return countType != null;
        }
    }

    record Element(String name, long count, List<Property> properties) {
        /** The index of the scalar property named one of {@code names}, or -1. */
        int scalar(String... names) {
            for (String n : names) {
                for (int i = 0; i < properties.size(); i++) {
                    if (properties.get(i).name().equals(n) && !properties.get(i).isList()) {
                        return i;
                    }
                }
            }
            return -1;
        }
    }

    /** Reads the header from {@code in}, leaving it at the first byte of the body. */
    static PlyHeader read(InputStream in, String file) throws IOException, PlyException {
        List<String> lines = lines(in, file);
        if (lines.isEmpty() || !isMagic(lines.get(0))) {
            throw new PlyException(file + ": not a PLY file (it must start with the line 'ply')");
        }
        Format format = null;
        List<Element> elements = new ArrayList<>();
        String skipped = null;
        int skippedLines = 0;
        for (int n = 1; n < lines.size(); n++) {
            String line = lines.get(n).trim();
            String[] w = line.split("\\s+");
            String at = file + ": header line " + (n + 1) + ": ";
            switch (w[0]) {
                case "", "comment", "obj_info" -> {
                }
                case "format" -> {
                    if (w.length != 3 || !w[2].startsWith("1.")) {
                        throw new PlyException(at + "expected 'format ascii|binary_little_endian|binary_big_endian 1.0', got '"
                                               + shown(line) + "'");
                    }
                    format = switch (w[1]) {
                        case "ascii" -> Format.ASCII;
                        case "binary_little_endian" -> Format.BINARY_LITTLE_ENDIAN;
                        case "binary_big_endian" -> Format.BINARY_BIG_ENDIAN;
                        default -> throw new PlyException(at + "unknown format '" + shown(w[1])
                                                          + "'; allowed: ascii, binary_little_endian, binary_big_endian");
                    };
                }
                case "element" -> {
                    if (w.length != 3) {
                        throw new PlyException(at + "expected 'element NAME COUNT', got '" + shown(line) + "'");
                    }
                    long count;
                    try {
                        count = Long.parseLong(w[2]);
                    } catch (NumberFormatException e) {
                        count = -1;
                    }
                    if (count < 0 || count > Integer.MAX_VALUE) {
                        throw new PlyException(at + "element '" + shown(w[1]) + "' needs a count from 0 to " + Integer.MAX_VALUE
                                               + ", got '" + shown(w[2]) + "'");
                    }
                    elements.add(new Element(w[1], count, new ArrayList<>()));
                }
                case "property" -> {
                    if (elements.isEmpty()) {
                        throw new PlyException(at + "a property before any element");
                    }
                    elements.get(elements.size() - 1).properties().add(property(w, line, at));
                }
                case "end_header" -> {
                }
                default -> {
                    if (skippedLines++ == 0) {
                        skipped = "header line " + (n + 1) + (KEYWORD.matcher(w[0]).matches() ? ": unknown keyword '" + w[0] + "'"
                                                                                            : ": no keyword");
                    }
                }
            }
        }
        if (format == null) {
            throw new PlyException(file + ": the header has no 'format' line");
        }
        List<String> warnings = skipped == null ? List.of()
            : List.of(file + ": " + skipped + ", line skipped" + (skippedLines > 1 ? " (" + skippedLines + " such lines)" : ""));
        return new PlyHeader(format, elements, lines.size(), warnings, skipped);
    }

    /** The first line: "ply", as trimesh and tinyply take it whatever its case and the white space around it. */
    private static boolean isMagic(String line) {
        return line.strip().equalsIgnoreCase("ply");
    }

    private static Property property(String[] w, String line, String at) throws PlyException {
        if (w.length == 3) {
            return new Property(w[2], type(w[1], at), null);
        }
        if (w.length == 5 && w[1].equals("list")) {
            PlyType count = type(w[2], at);
            if (!count.isInteger()) {
                throw new PlyException(at + "a list's count must be of an integer type, got '" + w[2] + "'");
            }
            return new Property(w[4], type(w[3], at), count);
        }
        throw new PlyException(at + "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME', got '"
                               + shown(line) + "'");
    }

    private static PlyType type(String name, String at) throws PlyException {
        PlyType t = PlyType.named(name);
        if (t == null) {
            throw new PlyException(at + "unknown property type '" + shown(name) + "'; allowed: " + PlyType.allowed());
        }
        return t;
    }

    /** The header's lines up to and including end_header (LF or CRLF), read byte by byte so that the body is left unread. */
    private static List<String> lines(InputStream in, String file) throws IOException, PlyException {
        List<String> lines = new ArrayList<>();
        byte[] line = new byte[256];
        int length = 0;
        int total = 0;
        int b;
        while ((b = in.read()) != -1) {
            if (++total > MAX_BYTES) {
                throw new PlyException(file + ": no 'end_header' in the first " + (MAX_BYTES >> 10) + " KiB (not a PLY header)");
            }
            if (b == '\n') {
                int end = length > 0 && line[length - 1] == '\r' ? length - 1 : length;
                String text = new String(line, 0, end, StandardCharsets.ISO_8859_1);
                lines.add(text);
                length = 0;
                if (text.trim().equals("end_header")) {
                    return lines;
                }
                if (lines.size() == 1 && !isMagic(text)) {
                    return lines; // not PLY: the caller says so
                }
                continue;
            }
            if (length == line.length) {
                line = java.util.Arrays.copyOf(line, 2 * length);
            }
            line[length++] = (byte) b;
        }
        if (lines.isEmpty() && length == 0) {
            throw new PlyException(file + ": the file is empty");
        }
        if (lines.isEmpty() || !isMagic(lines.get(0))) {
            lines.add(0, "");
            return lines;
        }
        throw new PlyException(file + ": the header ends without 'end_header' (truncated)");
    }

    /** Text from the file as it may be shown in a message: at most 40 characters, control characters escaped. */
    static String shown(String text) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < text.length() && s.length() < 40; i++) {
            char c = text.charAt(i);
            if (c < 0x20 || c == 0x7f || (c >= 0x80 && c < 0xa0)) {
                s.append(String.format("\\x%02x", (int) c));
            } else {
                s.append(c);
            }
        }
        return text.length() > 40 ? s + "..." : s.toString();
    }
}
