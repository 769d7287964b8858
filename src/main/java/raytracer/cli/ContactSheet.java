package raytracer.cli;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import raytracer.image.AtomicFile;

/**
 * Puts rendered images side by side with captions: {@code ContactSheet OUT.png IMAGE=CAPTION ...}.
 * Thumbnails are {@value #THUMB} pixels wide, {@value #COLUMNS} to a row.
 */
public final class ContactSheet {
    static final int THUMB = 256;
    static final int COLUMNS = 5;
    private static final int CAPTION = 22;

    private ContactSheet() {
    }

    public static void main(String[] args) {
        try {
            if (args.length < 2) {
                throw new IllegalArgumentException("usage: ContactSheet OUT.png IMAGE=CAPTION ...");
            }
            List<BufferedImage> images = new ArrayList<>();
            List<String> captions = new ArrayList<>();
            for (int i = 1; i < args.length; i++) {
                int eq = args[i].indexOf('=');
                Path file = Path.of(eq < 0 ? args[i] : args[i].substring(0, eq));
                BufferedImage image = ImageIO.read(file.toFile());
                if (image == null) {
                    throw new IOException("cannot read image " + file);
                }
                images.add(image);
                captions.add(eq < 0 ? file.getFileName().toString() : args[i].substring(eq + 1));
            }
            BufferedImage sheet = compose(images, captions);
            AtomicFile.write(Path.of(args[0]), out -> ImageIO.write(sheet, "png", out));
            System.err.println(args[0] + ": " + images.size() + " images");
        } catch (IOException | IllegalArgumentException e) {
            System.err.println("contact-sheet: error: " + e.getMessage());
            System.exit(1);
        }
    }

    static BufferedImage compose(List<BufferedImage> images, List<String> captions) {
        int rows = (images.size() + COLUMNS - 1) / COLUMNS;
        int cell = THUMB + CAPTION;
        BufferedImage sheet = new BufferedImage(COLUMNS * THUMB, rows * cell, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = sheet.createGraphics();
        g.setColor(new Color(24, 24, 28));
        g.fillRect(0, 0, sheet.getWidth(), sheet.getHeight());
        g.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_BICUBIC);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        boolean text = true;
        for (int i = 0; i < images.size(); i++) {
            BufferedImage image = images.get(i);
            int x = (i % COLUMNS) * THUMB;
            int y = (i / COLUMNS) * cell;
            int h = Math.min(THUMB, image.getHeight() * THUMB / image.getWidth());
            g.drawImage(image, x, y + (THUMB - h) / 2, THUMB, h, null);
            if (text) {
                try {
                    g.setColor(Color.WHITE);
                    g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
                    g.drawString(captions.get(i), x + 6, y + THUMB + 16);
                } catch (RuntimeException | Error e) {
                    text = false; // a machine without fonts still gets its thumbnails
                    System.err.println("contact-sheet: no fonts, captions left out (" + e + ")");
                }
            }
        }
        g.dispose();
        return sheet;
    }
}
