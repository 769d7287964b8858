package raytracer.io.obj;

/** A file that cannot be loaded; the message is one line naming the file and line. */
public final class ObjException extends Exception {
    private static final long serialVersionUID = 1L;

    public ObjException(String message) {
        super(message);
    }

    public ObjException(String message, Throwable cause) {
        super(message, cause);
    }
}
