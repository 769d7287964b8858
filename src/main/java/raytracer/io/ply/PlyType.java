package raytracer.io.ply;

import java.util.Locale;

/** The scalar types of a PLY property, under both the 1994 names and the sized ones (int8 ... float64). */
enum PlyType {
    CHAR(1, "char", "int8", Byte.MIN_VALUE, Byte.MAX_VALUE),
    UCHAR(1, "uchar", "uint8", 0, 0xff),
    SHORT(2, "short", "int16", Short.MIN_VALUE, Short.MAX_VALUE),
    USHORT(2, "ushort", "uint16", 0, 0xffff),
    INT(4, "int", "int32", Integer.MIN_VALUE, Integer.MAX_VALUE),
    UINT(4, "uint", "uint32", 0, 0xffffffffL),
    FLOAT(4, "float", "float32", 0, 0),
    DOUBLE(8, "double", "float64", 0, 0);

    /** Bytes in the binary formats. */
    final int size;
    private final String name;
    private final String sizedName;
    /** The values an integer type holds, [min, max]. */
    private final long min;
    private final long max;

    PlyType(int size, String name, String sizedName, long min, long max) {
        this.size = size;
        this.name = name;
        this.sizedName = sizedName;
        this.min = min;
        this.max = max;
    }

    boolean isInteger() {
        return this != FLOAT && this != DOUBLE;
    }

    /** Whether this integer type holds {@code v}. */
    boolean holds(long v) {
        return v >= min && v <= max;
    }

    /** The values an integer type holds, for a message: "0 to 255". */
    String range() {
        return min + " to " + max;
    }

    /** The type of this name, or null. */
    static PlyType named(String text) {
        String lower = text.toLowerCase(Locale.ROOT);
        for (PlyType t : values()) {
            if (t.name.equals(lower) || t.sizedName.equals(lower)) {
                return t;
            }
        }
        return null;
    }

    static String allowed() {
        StringBuilder s = new StringBuilder();
        for (PlyType t : values()) {
            s.append(s.length() == 0 ? "" : ", ").append(t.name).append('/').append(t.sizedName);
        }
        return s.toString();
    }

    @Override
    public String toString() {
        return name;
    }
}
