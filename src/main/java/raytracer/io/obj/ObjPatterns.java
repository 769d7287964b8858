package raytracer.io.obj;

import java.util.Set;
import java.util.regex.Pattern;

/**
 * The OBJ grammar as {@link ObjLoader} reads it, one precompiled pattern per kind of line, whose
 * matchers the loader reuses line after line; the numbers are read from the matched spans.
 */
final class ObjPatterns {
    static final String NUMBER = "[-+]?(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?";
    /** Also catch nan and inf, to report them as such rather than as garbage. */
    static final String ANY_NUMBER = "[-+]?(?:(?i:nan|inf(?:inity)?)|(?:\\d+\\.?\\d*|\\.\\d+)(?:[eE][-+]?\\d+)?)";
    static final Pattern KEYWORD = Pattern.compile("\\s*([^\\s#]+)");
    static final Pattern VERTEX = Pattern.compile(
        "\\s*v\\s+(" + ANY_NUMBER + ")\\s+(" + ANY_NUMBER + ")\\s+(" + ANY_NUMBER + ")(?:\\s+" + ANY_NUMBER + "){0,4}\\s*(?:#.*)?");
    static final Pattern TEXCOORD = Pattern.compile(
        "\\s*vt\\s+(" + ANY_NUMBER + ")(?:\\s+(" + ANY_NUMBER + "))?(?:\\s+" + ANY_NUMBER + ")?\\s*(?:#.*)?");
    static final Pattern NORMAL = Pattern.compile(
        "\\s*vn\\s+(" + ANY_NUMBER + ")\\s+(" + ANY_NUMBER + ")\\s+(" + ANY_NUMBER + ")\\s*(?:#.*)?");
    /** Fast paths for the commonest lines (the dragon is nothing else); on failure the general patterns decide. */
    static final Pattern VERTEX_PLAIN = Pattern.compile("v +(" + NUMBER + ") +(" + NUMBER + ") +(" + NUMBER + ") *");
    static final Pattern TRIANGLE_PLAIN = Pattern.compile("f +(\\d+) +(\\d+) +(\\d+) *");
    static final Pattern NAMED = Pattern.compile("\\s*(mtllib|usemtl|o|g|s)(?:\\s+(.*?))?\\s*");
    /** The keywords read without copying them out of the line. */
    static final String[] KNOWN = {"v", "vt", "vn", "f", "mtllib", "usemtl", "o", "g", "s"};
    /** Statements of the OBJ specification that a mesh of triangles has no use for. */
    static final Set<String> ACCEPTED = Set.of("l", "p", "cstype", "deg", "curv", "curv2", "surf", "parm", "end",
        "vp", "bmat", "step", "trim", "hole", "scrv", "sp", "con", "mg", "call", "csh", "maplib", "usemap", "ctech",
        "stech", "shadow_obj", "trace_obj", "lod", "bevel", "c_interp", "d_interp");

    private ObjPatterns() {
    }
}
