package raytracer.cli.converge;

import raytracer.image.ErrorMetrics;

/**
 * One measured render of the convergence benchmark: its configuration's name, samples per pixel,
 * area-light samples per shaded point, the render's wall time and its error against the reference.
 */
record ConvergeRow(String config, int spp, String lightSamples, double seconds, ErrorMetrics error) {
}
