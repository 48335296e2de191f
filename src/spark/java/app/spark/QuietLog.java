package app.spark;

import java.net.URISyntaxException;
import java.net.URL;

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
 * Spark's log on the driver: off, so that a run prints the command line's lines only (a failure is
 * one line, exit 1 or 2), unless asked for with {@code spark.log.level} (spark-submit's
 * {@code --conf spark.log.level=WARN}, or {@code -Dspark.log.level=WARN}). Spark loads its own
 * default profile (log level INFO to stderr, announced by a line of its own) when it finds
 * log4j unconfigured; a configuration of ours, with its root logger off, is one it keeps.
 */
final class QuietLog {
    /** The property that asks for Spark's log: a log4j level name. */
    static final String LEVEL = "spark.log.level";
    /** The configuration file with the root logger off, beside this class. */
    static final String FILE = "quiet-log4j2.properties";

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
}
