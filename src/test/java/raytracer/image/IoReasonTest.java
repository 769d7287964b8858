package raytracer.image;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.EOFException;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;
import org.junit.jupiter.api.Test;

/** A failure's reason is words, never a bare path or "(null)". */
class IoReasonTest {
    @Test
    void reasonsAreWords() {
        assertEquals("permission denied (/home/u/.cache)", IoReason.of(new AccessDeniedException("/home/u/.cache")));
        assertEquals("no such file or directory (/x)", IoReason.of(new NoSuchFileException("/x")));
        assertEquals("too many levels of symbolic links (/c)",
                     IoReason.of(new FileSystemException("/c", null, "Too many levels of symbolic links")));
        assertEquals("it ends early", IoReason.of(new EOFException()));
        assertEquals("IOException", IoReason.of(new IOException()));
        assertEquals("its checksum does not match", IoReason.of(new IOException("its checksum does not match")));
    }
}
