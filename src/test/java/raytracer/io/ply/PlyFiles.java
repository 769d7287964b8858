package raytracer.io.ply;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Consumer;

/** Small PLY files written by the tests: text as given, or a header followed by values packed in a byte order. */
final class PlyFiles {
    private PlyFiles() {
    }

    static Path text(Path dir, String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.write(file, text.getBytes(StandardCharsets.ISO_8859_1));
        return file;
    }

    static Path binary(Path dir, String name, String header, ByteOrder order, Consumer<ByteBuffer> body) throws IOException {
        ByteBuffer values = ByteBuffer.allocate(1 << 12).order(order);
        body.accept(values);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.write(header.getBytes(StandardCharsets.US_ASCII));
        out.write(values.array(), 0, values.position());
        Path file = dir.resolve(name);
        Files.write(file, out.toByteArray());
        return file;
    }
}
