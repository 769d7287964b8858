package raytracer.image;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * Run as a process of its own by {@link InterruptedWriteTest}: starts writing the file named by its
 * argument through {@link AtomicFile}, prints "writing" once part of it is out, and waits there to
 * be stopped by a signal, which makes the moment of the signal certain.
 */
final class WriterThatWaits {
    private WriterThatWaits() {
    }

    public static void main(String[] args) throws IOException {
        AtomicFile.write(Path.of(args[0]), out -> {
            out.write("half an image".getBytes(StandardCharsets.US_ASCII));
            out.flush();
            System.out.println("writing");
            System.out.flush();
            try {
                Thread.sleep(60_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
    }
}
