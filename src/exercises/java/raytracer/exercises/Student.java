package raytracer.exercises;

import static org.junit.jupiter.api.Assertions.fail;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.util.Arrays;
import java.util.stream.Collectors;

/**
 * Finds the class an exercise asks for by its name, so that the exercises' tests compile before it
 * exists, and says in one line what to write when it is missing or has the wrong shape.
 */
final class Student {
    private Student() {
    }

    /**
     * The public constructor of {@code className} taking {@code parameters}; fails the test with
     * "not implemented yet" when the class does not exist, and with what is wrong when it is not a
     * public {@code type} with that constructor.
     */
    static <T> Constructor<? extends T> constructor(int exercise, String className, Class<T> type, Class<?>... parameters) {
        String wanted = "a public class " + className + (type.isInterface() ? " implementing " : " extending ")
                        + type.getName() + " with a public constructor " + simpleName(className) + "("
                        + Arrays.stream(parameters).map(Class::getSimpleName).collect(Collectors.joining(", "))
                        + ") (docs/teaching.md, exercise " + exercise + ")";
        Class<?> found;
        try {
            found = Class.forName(className);
        } catch (ClassNotFoundException e) {
            return fail("not implemented yet: create " + wanted);
        }
        if (!type.isAssignableFrom(found) || !Modifier.isPublic(found.getModifiers())) {
            return fail(className + " exists but is not " + wanted);
        }
        try {
            return found.asSubclass(type).getConstructor(parameters);
        } catch (NoSuchMethodException e) {
            return fail(className + " has no such constructor: write " + wanted);
        }
    }

    /**
     * A new instance; an exception the constructor throws (IllegalArgumentException for a bad
     * parameter) reaches the caller as itself.
     */
    static <T> T create(Constructor<? extends T> constructor, Object... arguments) {
        try {
            return constructor.newInstance(arguments);
        } catch (InvocationTargetException e) {
            if (e.getCause() instanceof RuntimeException runtime) {
                throw runtime;
            }
            throw new AssertionError(constructor.getDeclaringClass().getName() + " threw " + e.getCause(), e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new AssertionError("cannot call " + constructor + ": " + e, e);
        }
    }

    private static String simpleName(String className) {
        return className.substring(className.lastIndexOf('.') + 1);
    }
}
