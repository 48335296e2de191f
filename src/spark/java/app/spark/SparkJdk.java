package app.spark;

import java.util.Optional;

/**
 * The JDKs Spark runs on. Spark 4.0 supports Java 17 and 21; on later JDKs its Hadoop security
 * code calls {@code Subject.getSubject}, which JDK 23 and later refuse, so a context fails to
 * start with an {@code UnsupportedOperationException} that names neither the JDK nor a remedy.
 * The command line, the Java API and the tests ask here first and say so in one line.
 */
final class SparkJdk {
    /** The oldest and newest Java feature release Spark 4.0 supports. */
    static final int OLDEST = 17, NEWEST = 21;

    private SparkJdk() {
    }

    /**
     * @param feature the Java feature release ({@code Runtime.version().feature()})
     * @param home    the JDK's folder ({@code java.home}), named in the message
     * @return why Spark cannot run on that JDK, in one line; empty where it can
     */
    static Optional<String> unsupported(int feature, String home) {
        if (feature >= OLDEST && feature <= NEWEST) return Optional.empty();
        return Optional.of("Spark 4.0 runs on Java " + OLDEST + " to " + NEWEST + ", and this is Java " + feature
                + " (" + home + "): run the Spark driver and its executors on JDK " + OLDEST + " or " + NEWEST
                + " (point JAVA_HOME at one); the local render runs on any JDK from " + OLDEST + " on");
    }

    /** @return why Spark cannot run on this JVM, in one line; empty where it can */
    static Optional<String> unsupported() {
        return unsupported(Runtime.version().feature(), System.getProperty("java.home"));
    }
}
