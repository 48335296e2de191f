/**
 * Rendering on an Apache Spark cluster, byte-identical to the local render: {@link
 * app.spark.SparkRenderer} (the Java API over a {@code JavaSparkContext}) cuts each image into
 * tiles rendered as tasks by the library's own render loop, and the command line's
 * {@code --spark MASTER} runs it through {@link app.spark.SparkEntry}. An entry point above the
 * library; Spark is a {@code provided} dependency, which neither the runnable jar nor a library
 * user gets.
 */
package app.spark;
