package raytracer.io.ply;

/** A PLY file that cannot be loaded; the message is one line naming the file and the header line or element. */
public final class PlyException extends Exception {
    private static final long serialVersionUID = 1L;

    public PlyException(String message) {
        super(message);
    }

    public PlyException(String message, Throwable cause) {
        super(message, cause);
    }
}
