package raytracer.cli.converge;

import java.util.ListResourceBundle;

/**
 * How converge words the options it shares with render ({@link raytracer.cli.RenderOptions}) where
 * they mean more or less here: picocli takes an option's description from the command's resource
 * bundle when the bundle holds the option's description key.
 */
public final class ConvergeHelp extends ListResourceBundle {
    @Override
    protected Object[][] getContents() {
        return new Object[][] {
            {"sampler", "Sample pattern of every configuration that names none (overrides the scene): ${COMPLETION-CANDIDATES}."},
            {"seed", "Seed of the measured renders; a self-rendered reference uses seeds made from it, never it. "
                     + "Default: ${DEFAULT-VALUE}."},
            {"cutoff", "Adaptive ray-tree cutoff of every configuration that names none (overrides the scene): branches weighing "
                       + "less than C and light samples adding less than C are not traced; a self-rendered reference traces the "
                       + "whole tree."},
            {"no-cache", "Neither read nor write cached references or meshes: a self-rendered reference is rendered and not "
                         + "kept, every mesh parsed and built."},
            {"quiet", "No progress, no notes: only the table."},
        };
    }
}
