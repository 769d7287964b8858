package raytracer.io.scene;

/** A scene that cannot be read; the message is one line that names the file, line and column. */
public final class SceneException extends Exception {
    private static final long serialVersionUID = 1L;

    public SceneException(String message) {
        super(message);
    }

    public SceneException(String message, Throwable cause) {
        super(message, cause);
    }
}
