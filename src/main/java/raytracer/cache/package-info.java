/**
 * Folders of files this program writes to reuse work across runs (parsed meshes with their BVHs,
 * converge's self-rendered references): how a file's content is identified, and how a folder is
 * kept under its cap without touching anything the program cannot prove it wrote.
 */
package raytracer.cache;
