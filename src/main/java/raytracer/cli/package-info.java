/**
 * The command line (picocli): the only place that prints or exits. This package holds the top
 * command, {@code render} ({@link raytracer.cli.RenderCommand}, the jar's entry point, which
 * checks render's own options in {@link raytracer.cli.OptionChecks}), and what its programs
 * share: how failures reach the user ({@link raytracer.cli.ErrorReport}), lines safe on a terminal
 * ({@link raytracer.cli.Terminal}), the progress bar, the version. The programs live beside it:
 * {@code raytracer.cli.render} (a render run, its frames and its report), {@code raytracer.cli.converge}
 * (the convergence benchmark, {@code render converge}) and {@code raytracer.cli.show} (the
 * {@code --show} window).
 */
package raytracer.cli;
