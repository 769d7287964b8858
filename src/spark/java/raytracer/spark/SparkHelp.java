package raytracer.spark;

import java.util.ListResourceBundle;

/**
 * How the Spark job words the options it shares with render ({@link raytracer.cli.RenderOptions})
 * where they mean more or less here: picocli takes an option's description from the command's
 * resource bundle when the bundle holds the option's description key.
 */
public final class SparkHelp extends ListResourceBundle {
    @Override
    protected Object[][] getContents() {
        return new Object[][] {
            {"threads", "Render threads per task, 1 to 32767. Default: the task's cores (spark.task.cpus)."},
            {"quiet", "No progress and no summary."},
            {"verbose", "Spark's own log at INFO, and stack traces with errors."},
        };
    }
}
