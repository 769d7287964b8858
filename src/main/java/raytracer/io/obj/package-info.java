/**
 * Wavefront OBJ and MTL files, read with precompiled regular expressions as the report did: the
 * line structure is recognised by patterns, numbers are parsed from the matched spans, and vertex
 * data goes into flat arrays. Errors name file and line; oddities that do not stop a load are
 * collected as warnings.
 */
package raytracer.io.obj;
