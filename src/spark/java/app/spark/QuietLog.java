package app.spark;

import java.net.URISyntaxException;
import java.net.URL;
import java.util.Locale;

import org.apache.logging.log4j.Level;
import org.apache.logging.log4j.LogManager;
import org.apache.logging.log4j.core.LoggerContext;
import org.apache.logging.log4j.core.appender.ConsoleAppender;
import org.apache.logging.log4j.core.config.Configurator;
import org.apache.logging.log4j.core.config.builder.api.ConfigurationBuilder;
import org.apache.logging.log4j.core.config.builder.api.ConfigurationBuilderFactory;
import org.apache.logging.log4j.core.config.builder.impl.BuiltConfiguration;
import org.apache.spark.SparkConf;

/**
 * Spark's log on the driver (and, through {@link #onExecutors}, on the executors): off, so that
 * a run prints the command line's lines only (a failure is one line, exit 1 or 2), unless asked for with {@code spark.log.level} (spark-submit's
 * {@code --conf spark.log.level=WARN}, or {@code -Dspark.log.level=WARN}). Spark loads its own
 * default profile (log level INFO to stderr, announced by a line of its own) when it finds
 * log4j unconfigured; a configuration of ours, with its root logger off, is one it keeps.
 */
final class QuietLog {
    /** The property that asks for Spark's log: a log4j level name. */
    static final String LEVEL = "spark.log.level";
    /** The configuration file with the root logger off, beside this class. */
    static final String FILE = "quiet-log4j2.properties";
    /** The executors' JVM options, to which {@link #onExecutors} adds the quiet default level. */
    static final String EXECUTOR_JVM_OPTIONS = "spark.executor.extraJavaOptions";
    /**
     * log4j's property of the level of its default configuration, the one an executor starts with
     * (no log4j file on its class path). Spark replaces that configuration by its INFO profile only
     * when the level is log4j's default, ERROR; any other level it keeps.
     */
    static final String LOG4J_LEVEL = "org.apache.logging.log4j.level";

    private QuietLog() {
    }

    /**
     * Turns the driver's log off, before Spark logs anything, unless {@link #LEVEL} is set.
     *
     * @return whether the log was turned off
     */
    static boolean unlessAsked() {
        if (System.getProperty(LEVEL) != null) return false;
        // Spark initialises its logging at its first log line after a reset, and spark-submit's
        // launcher resets it just before our main starts. Having once loaded its INFO profile (the
        // launcher did), Spark loads that profile again at every initialisation, over any
        // configuration in place: when the SparkContext started, its INFO log filled stderr. So
        // Spark initialises now (silently: no "Using Spark's default log4j profile" line), and
        // ours replaces what it loaded; initialised, Spark does not load it again.
        new SparkConf(false).initializeLogIfNecessary(false, true);
        URL file = QuietLog.class.getResource(FILE);
        if (file != null) {
            try {
                // The context's file rather than a configuration object: a reconfiguration of the
                // context (a reset of Spark's logging does one) then reads this file again.
                ((LoggerContext) LogManager.getContext(false)).setConfigLocation(file.toURI());
                if (LogManager.getRootLogger().getLevel() == Level.OFF) return true;
            } catch (URISyntaxException e) {
                throw new IllegalStateException("the quiet log configuration's address is not a URI: " + file, e);
            }
        }
        ConfigurationBuilder<BuiltConfiguration> b = ConfigurationBuilderFactory.newConfigurationBuilder();
        b.setStatusLevel(Level.OFF);
        b.setConfigurationName("raytracer-quiet");
        b.add(b.newAppender("stderr", "Console").addAttribute("target", ConsoleAppender.Target.SYSTEM_ERR));
        b.add(b.newRootLogger(Level.OFF).add(b.newAppenderRef("stderr")));
        Configurator.reconfigure(b.build());
        return true;
    }

    /**
     * The executors' side, in the configuration of the context about to start. A standalone
     * worker writes each executor's stderr to a file of its own (work/APP/ID/stderr), where Spark's
     * INFO log put about 3 lines a task (371 lines for a 100-tile teapot). The executors start with
     * log4j's default level set ({@link #LOG4J_LEVEL} added to {@link #EXECUTOR_JVM_OPTIONS}): OFF
     * when the driver is quiet, so that not even their start-up is logged; else the driver's
     * {@link #LEVEL}, so that {@code spark.log.level} is the executors' verbosity too, except
     * ERROR, which Spark takes for log4j unconfigured (its INFO profile then, on the executors).
     * Spark's own way, {@code spark.executor.syncLogLevel.enabled}, does not help here: an
     * executor applies the driver's level before it initialises its logging a second time, which
     * loads the INFO profile over it. A user's own log4j option, or a log4j file on the
     * executors' class path (a cluster's conf/log4j2.properties), is left as it is.
     *
     * @param conf  the configuration the context will start with
     * @param quiet whether the driver's log is off ({@link #unlessAsked()})
     */
    static void onExecutors(SparkConf conf, boolean quiet) {
        String options = conf.get(EXECUTOR_JVM_OPTIONS, "").trim();
        if (options.contains(LOG4J_LEVEL)) return;
        String level = quiet ? "OFF" : conf.get(LEVEL, "OFF").trim().toUpperCase(Locale.ROOT);
        // A level is a word (Spark refuses any but its own when the context starts); anything else
        // must not reach the executors' command line, where a space starts another option.
        if (!level.matches("[A-Z]+")) return;
        String option = "-D" + LOG4J_LEVEL + "=" + level;
        conf.set(EXECUTOR_JVM_OPTIONS, options.isEmpty() ? option : options + " " + option);
    }
}
