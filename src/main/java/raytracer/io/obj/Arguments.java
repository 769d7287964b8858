package raytracer.io.obj;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** The text after a statement's keyword, as names and paths are read from it in OBJ and MTL files. */
final class Arguments {
    /** A comment starts at a '#' that begins the text or follows a space: {@code mat#2} is a name. */
    private static final Pattern COMMENT = Pattern.compile("(?:^|\\s)#");

    private Arguments() {
    }

    /** The text before its comment, without surrounding spaces: {@code red # note} is {@code red}. */
    static String withoutComment(String text) {
        Matcher m = COMMENT.matcher(text);
        return (m.find() ? text.substring(0, m.start()) : text).strip();
    }

    /**
     * A path as exporters on Windows write it ({@code .\maps\wood.png}) with '/' separators, which
     * every platform reads; a '\' in a file's own name is rarer than a Windows path.
     */
    static String path(String text) {
        return text.replace('\\', '/');
    }
}
