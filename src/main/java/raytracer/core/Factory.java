package raytracer.core;

/** How a registered type is made from its entry's values ({@link Registrar}). */
@FunctionalInterface
public interface Factory<T> {
    /**
     * The object; a value it cannot use is a ParameterException from {@code p}, and an
     * IllegalArgumentException of a constructor is reported by the reader at the entry.
     */
    T make(Parameters p) throws ParameterException;
}
