package raytracer.core;

/**
 * A value of a scene file that a type cannot be made from; the message is one line that names the
 * file, line and column and the key ({@link Parameters}).
 */
public final class ParameterException extends Exception {
    private static final long serialVersionUID = 1L;

    public ParameterException(String message) {
        super(message);
    }

    public ParameterException(String message, Throwable cause) {
        super(message, cause);
    }
}
