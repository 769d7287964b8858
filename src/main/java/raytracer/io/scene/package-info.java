/**
 * Scene files (YAML, or JSON as its subset) read through SnakeYAML's node tree, so that every error
 * names the file, line and column, the key and what was expected. Format: docs/scene-format.md.
 */
package raytracer.io.scene;
