/**
 * {@code render converge}: a scene rendered at several sample counts or time budgets, for one or
 * more configurations, each image measured against a reference (an exact image, a given file, or
 * one rendered and cached), reported as a table, slopes and a log-log plot. docs/converge.md.
 */
package raytracer.cli.converge;
