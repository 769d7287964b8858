/**
 * Charts written as PNG (JFreeChart): a log-log line chart of several series with decade ticks, and
 * a grouped bar chart with error bars. The only package that uses the chart library.
 */
package raytracer.image.chart;
