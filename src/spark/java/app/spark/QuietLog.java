package app.spark;

import org.apache.logging.log4j.Level;
import org.apache.logging.log4j.core.appender.ConsoleAppender;
import org.apache.logging.log4j.core.config.Configurator;
import org.apache.logging.log4j.core.config.builder.api.ConfigurationBuilder;
import org.apache.logging.log4j.core.config.builder.api.ConfigurationBuilderFactory;
import org.apache.logging.log4j.core.config.builder.impl.BuiltConfiguration;

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

    private QuietLog() {
    }

    /**
     * Turns the driver's log off, before Spark logs anything, unless {@link #LEVEL} is set.
     *
     * @return whether the log was turned off
     */
    static boolean unlessAsked() {
        if (System.getProperty(LEVEL) != null) return false;
        ConfigurationBuilder<BuiltConfiguration> b = ConfigurationBuilderFactory.newConfigurationBuilder();
        b.setStatusLevel(Level.OFF);
        b.setConfigurationName("raytracer-quiet");
        b.add(b.newAppender("stderr", "Console").addAttribute("target", ConsoleAppender.Target.SYSTEM_ERR));
        b.add(b.newRootLogger(Level.OFF).add(b.newAppenderRef("stderr")));
        Configurator.reconfigure(b.build());
        return true;
    }
}
