/**
 * Scene files (YAML, or JSON as its subset) read through SnakeYAML's node tree, so that every error
 * names the file, line and column, the key and what was expected. Format: docs/scene-format.md.
 * A file is read once into a {@link raytracer.io.scene.SceneFile}, from which each frame of its
 * animation (a still has one) is loaded as a {@link raytracer.io.scene.LoadedScene}: the world, the
 * render settings it gives, and the {@link raytracer.io.scene.LoadReport} of the loading. Every
 * type an entry names is found in the {@link raytracer.core.Registry}; the built-in ones register
 * through {@link raytracer.io.scene.BuiltInTypes} and are made by the readers.
 */
package raytracer.io.scene;
