/**
 * The {@code --show} window: the image as its tiles finish, coded as the file will hold it
 * ({@link raytracer.cli.show.ShowWindow}, with its pixels, tone and scaling in classes free of
 * AWT), and whether a display is there to show it ({@link raytracer.cli.show.GraphicalDisplay}).
 * Those two are the only classes that touch AWT, and they are loaded only with {@code --show}.
 */
package raytracer.cli.show;
