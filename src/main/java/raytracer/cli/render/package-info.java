/**
 * One run of {@code render}: the scene read once and each frame loaded, prepared and rendered on
 * one pool ({@link raytracer.cli.render.RenderRun}), the files of {@code --frames} checked before
 * any is made ({@link raytracer.cli.render.FrameOutputs}), and what the run prints: warnings, the
 * summary line, the {@code --stats} breakdown ({@link raytracer.cli.render.RunReport}).
 */
package raytracer.cli.render;
