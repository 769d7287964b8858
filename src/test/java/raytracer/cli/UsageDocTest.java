package raytracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * docs/usage.md holds `render --help` as the program prints it, between two markers, so that the
 * page's list of options is the program's own and cannot fall behind it. After a change of an
 * option, {@code gradle junit -Ptests=raytracer.cli.UsageDocTest -PupdateDocs} writes it again.
 */
class UsageDocTest {
    private static final Path USAGE = Path.of("docs/usage.md");
    private static final String BEGIN = "<!-- render --help: begin -->\n";
    private static final String END = "<!-- render --help: end -->";

    @Test
    void theUsagePageShowsTheProgramsHelp() throws IOException {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        assertEquals(0, RenderCommand.run(new PrintWriter(out, true), new PrintWriter(err, true), "--help"), err.toString());
        String text = Files.readString(USAGE, StandardCharsets.UTF_8);
        int begin = text.indexOf(BEGIN);
        int end = text.indexOf(END);
        assertTrue(begin >= 0 && end > begin, USAGE + " lacks the markers " + BEGIN.strip() + " and " + END);
        String block = "```\n" + out.toString().stripTrailing() + "\n```\n";
        String shown = text.substring(begin + BEGIN.length(), end);
        if (Boolean.getBoolean("raytracer.updateDocs")) {
            Files.writeString(USAGE, text.substring(0, begin + BEGIN.length()) + block + text.substring(end), StandardCharsets.UTF_8);
            return;
        }
        assertEquals(block, shown, USAGE + " shows another --help than the program's (write it again with -PupdateDocs)");
    }
}
