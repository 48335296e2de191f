package renderer.junit;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.tools.ToolProvider;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The test-run listener: one line when a project's own course classes shadow the library's,
 * nothing when the library's classes are the ones that load; registered for JUnit's launcher.
 */
class ShadowedLibraryListenerTest {
    @TempDir
    Path dir;

    private String opened(ClassLoader tests) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Thread thread = Thread.currentThread();
        ClassLoader before = thread.getContextClassLoader();
        thread.setContextClassLoader(tests);
        try {
            new ShadowedLibraryListener(new PrintStream(err, true, StandardCharsets.UTF_8)).launcherSessionOpened(null);
        } finally {
            thread.setContextClassLoader(before);
        }
        return err.toString(StandardCharsets.UTF_8);
    }

    @Test
    @DisplayName("a project's own primitives.Point first on the class path: one line naming it and raytracer migrate")
    void shadowed() throws Exception {
        Path src = dir.resolve("primitives/Point.java");
        Files.createDirectories(src.getParent());
        Files.writeString(src, "package primitives;\npublic class Point {\n}\n");
        Path out = dir.resolve("out");
        Files.createDirectories(out);
        assertThat(ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", out.toString(), src.toString())).isZero();
        // The project's classes first, the library behind them: as a class path with both puts them.
        try (URLClassLoader project = new URLClassLoader(new URL[] { out.toUri().toURL() }, null) {
            @Override
            protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
                try {
                    return super.loadClass(name, resolve);
                } catch (ClassNotFoundException e) {
                    return ShadowedLibraryListenerTest.class.getClassLoader().loadClass(name);
                }
            }
        }) {
            List<String> lines = opened(project).lines().toList();
            assertThat(lines).singleElement().asString()
                    .startsWith("raytracer: these tests run on your own course classes, not the library's: primitives.Point from " + out)
                    .contains("raytracer migrate " + Path.of("").toAbsolutePath());
        }
    }

    @Test
    @DisplayName("the library's own classes: nothing printed")
    void notShadowed() {
        assertThat(opened(getClass().getClassLoader())).isEmpty();
    }

    @Test
    @DisplayName("registered for JUnit's launcher in the library's META-INF/services")
    void registered() throws Exception {
        try (var in = getClass().getResourceAsStream("/META-INF/services/org.junit.platform.launcher.LauncherSessionListener")) {
            assertThat(new String(in.readAllBytes(), StandardCharsets.UTF_8).strip())
                    .isEqualTo(ShadowedLibraryListener.class.getName());
        }
    }
}
