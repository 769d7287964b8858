/**
 * The render on Apache Spark ({@link raytracer.spark.SparkRender}, run by spark-submit): an
 * animation as a task per frame, a still as runs of its tile list put together on the driver,
 * files written atomically under fixed names on any Hadoop file system, each executor reading a
 * scene once ({@link raytracer.spark.ExecutorScenes}), our SnakeYAML before a cluster's. Its own
 * source set and thin jar (build/libs/render-spark.jar), compiled against Spark, which the cluster
 * provides; it renders through {@code raytracer.api}, as the command line does. docs/distributed.md.
 */
package raytracer.spark;
