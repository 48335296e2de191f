package app.cli;

import static app.cli.Cli.run;
import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.io.IOException;
import java.io.RandomAccessFile;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Pattern;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import app.cli.Cli.Run;
import renderer.Camera;
import scene.io.Limits;
import scene.io.RenderSettings;

/**
 * Scene files and options as a hostile user would write them: each ends in exit code
 * 2 and one line naming the place and the limit, at load, before anything is rendered, and leaves
 * no file behind; memory and signals are tried in a new JVM.
 */
class UntrustedInputTest {
    @TempDir
    Path dir;

    /** A scene around {@code inner}, with a camera unless {@code inner} has its own. */
    private static String scene(String inner) {
        String camera = inner.contains("<camera") ? ""
                : "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"10\" vp-distance=\"10\"/>\n";
        return "<scene name=\"hostile\">\n" + inner + "\n" + camera + "<image width=\"4\" height=\"4\"/>\n</scene>\n";
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    /** Exit code 2, one line that starts with the file and (when given) its position, and nothing written. */
    private void assertRefused(Run r, Path file, String position, String message) throws IOException {
        assertThat(r.exitCode()).as(r.err()).isEqualTo(RenderCommand.BAD_INPUT);
        assertThat(r.errLines()).hasSize(1);
        assertThat(r.errLines().get(0)).startsWith(file + position + ": ").contains(message);
        assertThat(r.out()).isEmpty();
        assertNothingWritten();
    }

    /** The folder holds only the inputs the test wrote: no image, no temporary file. */
    private void assertNothingWritten() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            assertThat(files.map(p -> p.getFileName().toString()))
                    .allMatch(name -> name.endsWith(".xml") || name.endsWith(".obj") || name.endsWith(".txt"));
        }
    }

    private Run render(Path scene) {
        return run(scene.toString(), "-o", dir.resolve("out.png").toString());
    }

    /** A light with a radius, written after the element under test so that its columns stay put. */
    private static final String SOFT_LIGHT = "<lights><point-light color=\"100 100 100\" position=\"0 5 0\" radius=\"1\"/></lights>";

    static Stream<Arguments> badValues() {
        return Stream.of(
                Arguments.of("an attenuation of nothing: kc 0 and no kl, kq", "<lights><point-light color=\"100 100 100\""
                        + " position=\"0 0 0\" kc=\"0\"/></lights>", "2:59",
                        "point light attenuation coefficients must not all be zero"),
                Arguments.of("an emission of 1e308", "<geometries><sphere center=\"0 0 -5\" radius=\"1\""
                        + " emission=\"1e308 0 0\"/></geometries>", "2:48", "1e308 is larger than 1000000000 in magnitude"),
                Arguments.of("a kd of 1e308", "<geometries><sphere center=\"0 0 -5\" radius=\"1\"><material kd=\"1e308\"/>"
                        + "</sphere></geometries>", "2:58", "1e308 is larger than 1000000000 in magnitude"),
                Arguments.of("a ks of 1e308", "<geometries><sphere center=\"0 0 -5\" radius=\"1\"><material"
                        + " ks=\"1 1 1e308\"/></sphere></geometries>", "2:58", "1e308 is larger than 1000000000 in magnitude"),
                Arguments.of("a view plane of 1e300", "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\""
                        + " vp-size=\"1e300\" vp-distance=\"1\"/>", "2:56", "1e300 is larger than 1000000000 in magnitude"),
                Arguments.of("a view plane 1e-300 away", "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\""
                        + " vp-size=\"1\" vp-distance=\"1e-300\"/>", "2:68", "1e-300 is closer to 0 than 1e-9"),
                Arguments.of("a view plane lost in the location's precision", "<camera location=\"1e9 0 0\""
                        + " direction=\"1 0 0\" up=\"0 1 0\" vp-size=\"1e-9\" vp-distance=\"1e-9\"/>", "2:72",
                        "no ray through the view plane"),
                Arguments.of("a 65536x65536 grid", "<render><anti-aliasing mode=\"random\" grid=\"65536 65536\"/></render>",
                        "2:38", "has 4294967296 samples per pixel, more than the limit of 65536"),
                Arguments.of("adaptive depth 6 × beams of 256 × 16 shadow samples of a soft light",
                        "<render beam-size=\"256\"><anti-aliasing mode=\"adaptive\" depth=\"6\"/></render>" + SOFT_LIGHT, "2:56",
                        "more than the limit of 16777216"),
                Arguments.of("65536 lens samples", "<render><depth-of-field focal-distance=\"10\" aperture=\"1\""
                        + " samples=\"65537\"/></render>", "2:58", "depth-of-field samples must be from 1 to 65536"),
                Arguments.of("lens samples × beams × shadow samples of a soft light", "<render beam-size=\"100\"><depth-of-field"
                        + " focal-distance=\"10\" aperture=\"1\" samples=\"60000\"/></render>" + SOFT_LIGHT, "2:74",
                        "more than the limit of 16777216"),
                Arguments.of("beams of 2048 × 4096 shadow samples of one soft light", "<render beam-size=\"2048\""
                        + " shadow-samples=\"4096\"/>" + SOFT_LIGHT, "2:9", "(1 + 4096 shadow samples × 1 soft light"
                        + " + 0 other lights) is 16785409 rays per pixel, more than the limit of 16777216"),
                Arguments.of("beams of 2^31 - 1 rays", "<render beam-size=\"2147483647\"/>", "2:9",
                        "more than the limit of 16777216"),
                Arguments.of("100000 threads", "<render threads=\"100000\"/>", "2:9",
                        "thread count 100000 is more than the limit of " + Camera.maxThreads()),
                Arguments.of("elements nested 9 deep", "<geometries><sphere center=\"0 0 -5\" radius=\"1\"><material>"
                        + "<a><b><c><d><e/></d></c></b></a></material></sphere></geometries>", "2:70",
                        "<e> is nested 9 elements deep (expected at most 8, the limit)"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badValues")
    @DisplayName("a bad value is reported at load, at its place")
    void badValue(String name, String inner, String position, String message) throws IOException {
        Path file = write("scene.xml", scene(inner));
        assertRefused(render(file), file, ":" + position, message);
    }

    @Nested
    @DisplayName("meshes: regular files within the limits, streamed")
    class Meshes {
        @Test
        @DisplayName("<mesh file=\"/dev/zero\"/>: refused before reading")
        void device() throws IOException {
            Path file = write("scene.xml", scene("<geometries><mesh file=\"/dev/zero\"/></geometries>"));
            assertRefused(render(file), file, ":2:19", "/dev/zero is not an OBJ file");
        }

        @ParameterizedTest(name = "{0}")
        @ValueSource(strings = { "/etc/passwd", "/proc/self/status", "../outside.obj" })
        @DisplayName("a mesh that is not an OBJ file inside the scene's folder: refused unread, exit 2")
        void outside(String mesh) throws IOException {
            Path file = write("scene.xml", scene("<geometries><mesh file=\"" + mesh + "\"/></geometries>"));
            assertRefused(render(file), file, ":2:19", mesh.endsWith(".obj") ? "is outside the folder meshes are read from"
                    : "is not an OBJ file");
        }

        @Test
        @DisplayName("--mesh-root DIR reads meshes from another folder")
        void meshRoot() throws IOException {
            Path models = Files.createDirectories(dir.resolve("models"));
            Files.writeString(models.resolve("tri.obj"), "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
            Path scenes = Files.createDirectories(dir.resolve("scenes"));
            Path file = Files.writeString(scenes.resolve("scene.xml"), scene("<geometries><mesh file=\"../models/tri.obj\"/></geometries>"));
            assertThat(run(file.toString(), "-q", "-o", dir.resolve("out.png").toString()).exitCode()).isEqualTo(RenderCommand.BAD_INPUT);
            Run r = run(file.toString(), "-q", "--mesh-root", dir.toString(), "-o", dir.resolve("out.png").toString());
            assertThat(r.exitCode()).as(r.err()).isZero();
        }

        @Test
        @DisplayName("an OBJ with a line longer than the limit: refused at that line")
        void longLine() throws IOException {
            write("long.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# " + "x".repeat(Limits.MAX_OBJ_LINE_LENGTH) + "\n");
            Path file = write("scene.xml", scene("<geometries><mesh file=\"long.obj\"/></geometries>"));
            assertRefused(render(file), file, ":2:19", "long.obj:5: a line longer than 65536 characters (the limit)");
        }

        @Test
        @DisplayName("an OBJ vertex beyond the scene's number range: refused at load, not while rendering")
        void hugeVertex() throws IOException {
            write("far.obj", "v 1e20 0 0\nv 1e20 1e20 0\nv 1e20 0 1e20\nf 1 2 3\n");
            Path file = write("scene.xml", scene("<geometries><mesh file=\"far.obj\"/></geometries>"));
            assertRefused(render(file), file, ":2:19", "far.obj:0: a vertex coordinate of magnitude 1.0E20, larger than"
                    + " 1000000000 (the limit of a scene's numbers)");
        }

        @Test
        @DisplayName("an OBJ file larger than the limit: refused before reading (a sparse file, no disk used)")
        void largeFile() throws IOException {
            try (RandomAccessFile obj = new RandomAccessFile(dir.resolve("large.obj").toFile(), "rw")) {
                obj.setLength(Limits.MAX_OBJ_BYTES + 1);
            }
            Path file = write("scene.xml", scene("<geometries><mesh file=\"large.obj\"/></geometries>"));
            assertRefused(render(file), file, ":2:19", "large.obj:0: the file has 268435457 bytes, more than the limit of"
                    + " 268435456 bytes");
        }

        @Test
        @DisplayName("a mesh that does not fit in the heap: exit code 1, one line naming the file, its size and what was read, at once (a new JVM of 32 MB)")
        void notEnoughMemory() throws Exception {
            StringBuilder obj = new StringBuilder();
            int n = 1_200_000;
            for (int i = 0; i < n; ++i) obj.append("v ").append(i % 97).append(' ').append(i % 89).append(" 0\n");
            obj.append("f 1 2 3\n");
            write("big.obj", obj.toString());
            Path file = write("scene.xml", scene("<geometries><mesh file=\"big.obj\"/></geometries>"));
            Run r = Cli.runJava(dir, "-Xmx32m", file.toString(), "-o", dir.resolve("out.png").toString());
            assertThat(r.exitCode()).as(r.err()).isEqualTo(RenderCommand.FAILURE);
            assertThat(r.errLines()).hasSize(1);
            // the file's size (13 MB), how far the reader got, the limit and the option
            assertThat(r.errLines().get(0)).matches("raytracer: the OBJ file " + Pattern.quote(dir.resolve("big.obj").toString())
                    + " \\(" + (obj.length() + (1 << 19)) / (1 << 20) + " MB\\) did not fit in memory: (Java ran out before a"
                    + " vertex was read|0 triangles and \\d+ vertices read when Java ran out); Java may use at most \\d+ MB"
                    + " here \\(give Java more memory with -Xmx; on Spark's driver, spark-submit --driver-memory\\)");
            assertNothingWritten();
        }
    }

    @Nested
    @DisplayName("the scene file itself")
    class SceneFile {
        @Test
        @DisplayName("/dev/zero as the scene: refused before reading")
        void device() throws IOException {
            Run r = run("/dev/zero", "-o", dir.resolve("out.png").toString());
            assertRefused(r, Path.of("/dev/zero"), "", "not a regular file");
        }

        @Test
        @DisplayName("a scene file larger than the limit: refused before parsing")
        void large() throws IOException {
            Path file = dir.resolve("large.xml");
            try (RandomAccessFile xml = new RandomAccessFile(file.toFile(), "rw")) {
                xml.setLength(Limits.MAX_SCENE_BYTES + 1);
            }
            assertRefused(render(file), file, "", "the file has 16777217 bytes, more than the limit of 16777216 bytes");
        }
    }

    @Nested
    @DisplayName("the image name is a name: the image goes to images/, only -o chooses another place")
    class ImageName {
        @Test
        @DisplayName("<image name=\"/absolute/x\">")
        void absolute() throws IOException {
            Path target = dir.resolve("x");
            Path file = write("scene.xml", "<scene name=\"hostile\">\n<image name=\"" + target + "\"/>\n"
                    + "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"1\" vp-distance=\"1\"/></scene>");
            Run r = run(file.toString());
            assertRefused(r, file, ":2:8", "the image name '" + target + "' is a path, not a name (it contains '/')");
            assertThat(Path.of(target + ".png")).doesNotExist();
        }

        @ParameterizedTest(name = "U+{0}")
        @ValueSource(strings = { "009B", "3164", "2028", "00A0" })
        @DisplayName("a name with a control, invisible or look-alike character: refused, the character escaped on stderr")
        void hidden(String hex) throws IOException {
            String c = Character.toString(Integer.parseInt(hex, 16));
            Path file = write("scene.xml", "<scene name=\"hostile\">\n<image name=\"a" + c + "[31mb\"/>\n"
                    + "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"1\" vp-distance=\"1\"/></scene>");
            Run r = run(file.toString());
            assertRefused(r, file, ":2:8", "the image name contains U+" + hex);
            assertThat(r.errLines()).hasSize(1);
            assertThat(r.err()).contains("\\u" + hex).doesNotContain(c);
        }

        @ParameterizedTest(name = "name=\"{0}\"")
        @ValueSource(strings = { "../../x", "..", "a\\b", "c:x" })
        @DisplayName("a name that leaves images/")
        void relative(String name) throws IOException {
            Path file = write("scene.xml", "<scene name=\"hostile\">\n<image name=\"" + name + "\"/>\n"
                    + "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"1\" vp-distance=\"1\"/></scene>");
            Path escape = Path.of("images", name + ".png").normalize();
            Object before = state(escape);
            Run r = run(file.toString());
            assertRefused(r, file, ":2:8", "the image name '" + name + "'");
            assertThat(state(escape)).as("%s, outside images/", escape).isEqualTo(before);
        }

        @Test
        @DisplayName("the scene name, when it names the image, is held to the same rule")
        void sceneName() throws IOException {
            Path file = write("scene.xml", "<scene name=\"../x\">\n"
                    + "<camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\" vp-size=\"1\" vp-distance=\"1\"/></scene>");
            Object before = state(Path.of("x.png"));
            assertRefused(run(file.toString()), file, ":1:8", "the scene name names the image");
            assertThat(state(Path.of("x.png"))).isEqualTo(before);
        }

        /**
         * What a refused run must leave as it was: absent, or (when something outside the test put
         * a file there, e.g. in the parent of a CI checkout) the same size and modification time.
         */
        private Object state(Path p) throws IOException {
            return Files.exists(p) ? Files.size(p) + " bytes, modified " + Files.getLastModifiedTime(p) : "absent";
        }
    }

    @Nested
    @DisplayName("options")
    class Options {
        @Test
        @DisplayName("--threads 100000: a usage error naming the limit, no thread started")
        void threads() throws IOException {
            Path file = write("scene.xml", scene(""));
            Run r = run(file.toString(), "--threads", "100000", "-o", dir.resolve("out.png").toString());
            assertThat(r.exitCode()).isEqualTo(RenderCommand.BAD_INPUT);
            assertThat(r.errLines()).containsExactly("raytracer: --threads: thread count 100000 is more than the limit of "
                    + Camera.maxThreads() + " (" + Camera.MAX_THREADS_PER_CORE + " per core, "
                    + Runtime.getRuntime().availableProcessors() + " cores)", "Try 'java -jar raytracer.jar --help' for more information.");
            assertNothingWritten();
        }

        @Test
        @DisplayName("--aa random with the file's large grid over the ray budget: a usage error")
        void antiAliasing() throws IOException {
            assertAntiAliasingRefused("<render beam-size=\"128\"><anti-aliasing mode=\"none\" grid=\"256 256\"/></render>",
                    "65536 samples per pixel × (1 + 2 beams of 128 rays: reflection and transmission) × (1 + 16 shadow"
                            + " samples × 0 soft lights + 0 other lights) is 16842752");
        }

        @Test
        @DisplayName("--aa random over the ray budget only with the file's soft lights: the usage error counts them")
        void antiAliasingWithLights() throws IOException {
            // 16384 samples × 33 × (1 + 16 × 2 soft lights) is over 2^24; without the lights, 540,672 is not.
            assertAntiAliasingRefused("<lights><point-light color=\"1 1 1\" position=\"0 0 1\" radius=\"1\"/>"
                            + "<point-light color=\"1 1 1\" position=\"0 1 1\" radius=\"1\"/></lights>"
                            + "<render><anti-aliasing mode=\"none\" grid=\"128 128\"/></render>",
                    "16384 samples per pixel × (1 + 2 beams of 16 rays: reflection and transmission) × (1 + 16 shadow"
                            + " samples × 2 soft lights + 0 other lights) is 17842176");
        }

        /** {@code --aa random} over a scene of {@code inner}: exit 2, the budget's line with {@code factors}, nothing written. */
        private void assertAntiAliasingRefused(String inner, String factors) throws IOException {
            Path file = write("scene.xml", scene(inner));
            Run r = run(file.toString(), "--aa", "random", "-o", dir.resolve("out.png").toString());
            assertThat(r.exitCode()).isEqualTo(RenderCommand.BAD_INPUT);
            assertThat(r.errLines().get(0)).isEqualTo("raytracer: --aa RANDOM: RANDOM sampling with " + factors
                    + " rays per pixel, more than the limit of " + RenderSettings.MAX_RAYS_PER_PIXEL);
            assertNothingWritten();
        }

        @Test
        @DisplayName("--help fits 80 columns: no line wraps, and every Limits line stays in its table")
        void helpFits() {
            List<String> lines = run("--help").out().lines().toList();
            assertThat(lines).allSatisfy(line -> assertThat(line.length()).as(line).isLessThanOrEqualTo(80));
            List<String> limits = lines.subList(lines.indexOf("Limits (docs/scene-format.md, \"Limits\"):") + 1, lines.size());
            assertThat(limits).isNotEmpty().allSatisfy(line -> assertThat(line).startsWith("  "));
        }

        @Test
        @DisplayName("--help states every limit")
        void help() {
            Run r = run("--help");
            assertThat(r.out()).contains("Limits", "at most " + Camera.MAX_THREADS_PER_CORE + " per core",
                    "at most " + Camera.MAX_SAMPLES_PER_PIXEL, "at most " + RenderSettings.MAX_RAYS_PER_PIXEL,
                    "at most " + RenderSettings.MAX_PIXELS + " pixels", "at most " + Limits.MAX_SCENE_BYTES + " bytes",
                    "nested at most " + Limits.MAX_NESTING_DEPTH, "at most " + Limits.MAX_OBJ_BYTES + " bytes",
                    "at most " + Limits.MAX_OBJ_LINE_LENGTH + " characters", "numbers at most 1e9 in magnitude",
                    "at least 1e-9");
        }
    }

    /**
     * A signal while the PNG is written: the JVM's shutdown hooks run, and the half-written
     * temporary file beside the target is deleted. A 4000×4000 image takes long enough to encode
     * for the test to see the temporary file and signal then.
     */
    @ParameterizedTest(name = "SIG{0}")
    @ValueSource(strings = { "TERM", "INT" })
    @EnabledOnOs({ OS.LINUX, OS.MAC })
    @DisplayName("a signal while the image is written leaves no temporary file")
    void signalWhileWriting(String signal) throws Exception {
        assumeFalse(signal.equals("INT") && sigintIgnored(),
                "SIGINT is ignored here (a shell's background job): the JVM it starts keeps ignoring it");
        Path file = write("scene.xml", "<scene name=\"big\"><camera location=\"0 0 0\" direction=\"0 0 -1\" up=\"0 1 0\""
                + " vp-size=\"1\" vp-distance=\"1\"/><image width=\"4000\" height=\"4000\" grid-interval=\"3\"/>"
                + "<render threads=\"1\"/></scene>");
        Process process = Cli.startJava(dir, "-Xmx512m", file.toString(), "-o", dir.resolve("out.png").toString(), "-q");
        Path tmp = null;
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (tmp == null && process.isAlive() && System.nanoTime() < deadline) {
            try (Stream<Path> files = Files.list(dir)) {
                tmp = files.filter(p -> p.getFileName().toString().startsWith(".out.png")).findFirst().orElse(null);
            }
            if (tmp == null) Thread.sleep(2);
        }
        assertThat(tmp).as("the temporary file appeared while the process ran").isNotNull();
        new ProcessBuilder("kill", "-" + signal, Long.toString(process.pid())).start().waitFor();
        Run r = Cli.finished(dir, process);
        assertThat(r.exitCode()).as(r.err()).isEqualTo(128 + (signal.equals("TERM") ? 15 : 2));
        assertThat(tmp).doesNotExist();
        assertThat(dir.resolve("out.png")).doesNotExist();
        assertNothingWritten();
    }

    /**
     * Whether this process ignores SIGINT, as a job a non-interactive shell starts in the
     * background does: a JVM started from it keeps ignoring the signal (HotSpot leaves an
     * inherited SIG_IGN alone), so a SIGINT sent to it does nothing. Linux says so in
     * /proc/self/status (SigIgn, a hexadecimal mask, signal n at bit n - 1); elsewhere, no.
     */
    private static boolean sigintIgnored() throws IOException {
        Path status = Path.of("/proc/self/status");
        if (!Files.isReadable(status)) return false;
        for (String line : Files.readAllLines(status))
            if (line.startsWith("SigIgn:")) return (Long.parseUnsignedLong(line.substring(7).strip(), 16) & 0b10) != 0;
        return false;
    }
}
