package raytracer.io.ply;

import java.util.Locale;

/** The scalar types of a PLY property, under both the 1994 names and the sized ones (int8 ... float64). */
enum PlyType {
    CHAR(1, "char", "int8"), UCHAR(1, "uchar", "uint8"), SHORT(2, "short", "int16"), USHORT(2, "ushort", "uint16"),
    INT(4, "int", "int32"), UINT(4, "uint", "uint32"), FLOAT(4, "float", "float32"), DOUBLE(8, "double", "float64");

    /** Bytes in the binary formats. */
    final int size;
    private final String name;
    private final String sizedName;

    PlyType(int size, String name, String sizedName) {
        this.size = size;
        this.name = name;
        this.sizedName = sizedName;
    }

    boolean isInteger() {
        return this != FLOAT && this != DOUBLE;
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
