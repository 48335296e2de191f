package app.migrate;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the migration takes from the machine: JUnit's jars from the local Maven repository, fetched
 * there when the library's first build (tests skipped) left some out, and the library's clone.
 */
class ToolchainTest {
    @TempDir
    Path dir;

    /** The five JUnit artifacts' jars, as Maven lays them out, for the versions JUnit 5.11.3 uses. */
    private static final List<String> JUNIT = List.of("org/junit/jupiter/junit-jupiter-api/5.11.3/junit-jupiter-api-5.11.3.jar",
            "org/junit/jupiter/junit-jupiter-params/5.11.3/junit-jupiter-params-5.11.3.jar",
            "org/junit/platform/junit-platform-commons/1.11.3/junit-platform-commons-1.11.3.jar",
            "org/opentest4j/opentest4j/1.3.0/opentest4j-1.3.0.jar",
            "org/apiguardian/apiguardian-api/1.1.2/apiguardian-api-1.1.2.jar");

    private Toolchain toolchain(Path repository, String maven) {
        return new Toolchain(dir.resolve("lib.jar"), Toolchain.junitJars(repository, "5.11.3"), repository,
                "io.github.raytracer:raytracer:1.0.0-SNAPSHOT", "5.11.3", 17, maven);
    }

    private void put(Path repository, String jar) throws IOException {
        Files.createDirectories(repository.resolve(jar).getParent());
        Files.write(repository.resolve(jar), new byte[0]);
    }

    /**
     * A stand-in for {@code mvn} that logs its arguments and, asked for JUnit's parameterized
     * tests with their dependencies, puts every JUnit jar into the repository it was given.
     */
    private String fakeMaven() throws IOException {
        assumeTrue(!System.getProperty("os.name", "").startsWith("Windows"), "a POSIX shell script stands in for Maven");
        Path script = dir.resolve("mvn");
        StringBuilder text = new StringBuilder("#!/bin/sh\necho \"$@\" >> \"" + dir.resolve("mvn.log") + "\"\nrepo=\n"
                + "for a in \"$@\"; do case \"$a\" in -Dmaven.repo.local=*) repo=${a#-Dmaven.repo.local=};; esac; done\n"
                + "case \" $* \" in *\" -Dartifact=org.junit.jupiter:junit-jupiter-params:5.11.3 \"*\"-Dtransitive=true \"*) ;; *) exit 1;; esac\n");
        for (String jar : JUNIT)
            text.append("mkdir -p \"$repo/").append(jar, 0, jar.lastIndexOf('/')).append("\" && : > \"$repo/").append(jar).append("\"\n");
        Files.writeString(script, text, StandardCharsets.UTF_8);
        assertThat(script.toFile().setExecutable(true)).isTrue();
        return script.toString();
    }

    @Nested
    @DisplayName("JUnit's jars")
    class JUnitJars {
        @Test
        @DisplayName("all there: taken as they are, Maven not asked")
        void allThere() throws IOException {
            Path repository = dir.resolve("m2");
            for (String jar : JUNIT) put(repository, jar);
            String maven = fakeMaven();
            assertThat(toolchain(repository, maven).junitFetchedIfMissing()).hasSize(5);
            assertThat(dir.resolve("mvn.log")).doesNotExist();
        }

        @Test
        @DisplayName("the parameterized tests' jar missing (the library built with -DskipTests): fetched with its dependencies")
        void fetched() throws IOException {
            Path repository = dir.resolve("m2");
            put(repository, JUNIT.get(0)); // the API, which the library's image assertions compile against
            Toolchain tools = toolchain(repository, fakeMaven());
            assertThat(tools.junit()).hasSize(1);
            assertThat(tools.junitFetchedIfMissing()).hasSize(5)
                    .anySatisfy(j -> assertThat(j.getFileName()).hasToString("junit-jupiter-params-5.11.3.jar"));
            assertThat(Files.readString(dir.resolve("mvn.log"))).contains("dependency:get",
                    "-Dartifact=org.junit.jupiter:junit-jupiter-params:5.11.3", "-Dtransitive=true");
        }

        @Test
        @DisplayName("no Maven to ask: what there is, for the caller to say what is missing")
        void noMaven() throws IOException {
            Path repository = dir.resolve("m2");
            put(repository, JUNIT.get(0));
            assertThat(toolchain(repository, null).junitFetchedIfMissing()).hasSize(1);
        }
    }

    @Nested
    @DisplayName("the library's clone")
    class Clone {
        @Test
        @DisplayName("the folder of target/ when it holds a pom (this build's own classes)")
        void ofThisBuild() throws IOException {
            Path clone = Files.createDirectories(dir.resolve("raytracer"));
            Files.writeString(clone.resolve("pom.xml"), "<project/>");
            Path jar = Files.createDirectories(clone.resolve("target")).resolve("raytracer.jar");
            assertThat(new Toolchain(jar, List.of(), dir, "g:a:1", "5.11.3", 17, null).libraryClone()).contains(clone.toAbsolutePath());
        }

        @Test
        @DisplayName("none for a jar elsewhere (a downloaded one, the local repository's)")
        void elsewhere() {
            assertThat(new Toolchain(dir.resolve("lib/raytracer.jar"), List.of(), dir, "g:a:1", "5.11.3", 17, null).libraryClone())
                    .isEmpty();
        }
    }
}
