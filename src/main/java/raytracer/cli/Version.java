package raytracer.cli;

import picocli.CommandLine;

/** The version that {@code render --version} prints: the jar manifest's, and the Java it runs on. */
public final class Version implements CommandLine.IVersionProvider {
    @Override
    public String[] getVersion() {
        String v = RenderCommand.class.getPackage().getImplementationVersion();
        return new String[] {"render " + (v != null ? v : "(development build)")
                             + " on Java " + System.getProperty("java.version")};
    }
}
