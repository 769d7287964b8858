package raytracer.core;

/**
 * One thing the scene analysis decided a render need not do: {@code what} is left out (a term, a
 * ray, a light, a mesh), {@code why} it changes no pixel, and which {@link Skipped} count measures
 * the saving ({@link Skipped#UNCOUNTED} when none does).
 */
public record Skip(int counter, String what, String why) {
}
