/**
 * Tracers (Suffern, chapters 3, 14, 18 and 24): {@code RayCast} shades primary rays only,
 * {@code Whitted} recurses through mirrors and glass, {@code AreaLighting} recurses too and has
 * materials sample the lights ({@code areaLightShade}), as area lights need; {@code BvhCost} is the
 * report's debug view.
 */
package raytracer.tracers;
