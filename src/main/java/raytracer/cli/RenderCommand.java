package raytracer.cli;
public final class RenderCommand { public static void main(String[] a) { System.out.println("hi"); } }
