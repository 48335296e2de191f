package app.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The same images whichever walk the JVM takes: each scene of {@code scenes/} and a mesh of 10⁵
 * triangles rendered by the command line in a JVM with {@code jdk.incubator.vector} and
 * {@code -Draytracer.simd=true} (the vector walk from the first ray), in one with the module only
 * (the default: a short render walks its wide tree in scalar code, lane leaves included), and in
 * one with {@code -Draytracer.simd=false} (the scalar walk of a binary tree), byte for byte.
 */
@DisplayName("the command line's images are the same bytes with the vector walk and the scalar walk")
class WalkImagesTest {
    private static final List<String> VECTOR = List.of("-Xshare:off", "--add-modules", "jdk.incubator.vector",
            "-Draytracer.simd=true");
    private static final List<String> DEFAULT = List.of("-Xshare:off", "--add-modules", "jdk.incubator.vector");
    private static final List<String> SCALAR = List.of("-Xshare:off", "--add-modules", "jdk.incubator.vector",
            "-Draytracer.simd=false");

    static Stream<String> scenes() {
        return Stream.of("two-colors.xml", "showcase.xml", "glossy.xml", "teapot.xml", "bumpy sphere of 10⁵ triangles");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void sameBytes(String scene, @TempDir Path dir) throws IOException, InterruptedException {
        Path file = scene.endsWith(".xml") ? app.Project.file("scenes", scene) : bumpySphere(dir);
        byte[] vector = render(dir, file, VECTOR, "vector");
        byte[] scalar = render(dir, file, SCALAR, "scalar");
        byte[] gated = render(dir, file, DEFAULT, "default");
        assertThat(vector).as("the vector walk's PNG against the scalar walk's").isEqualTo(scalar);
        assertThat(gated).as("the default JVM's PNG (the wide tree, scalar until compiled) against the scalar walk's")
                .isEqualTo(scalar);
    }

    private static byte[] render(Path dir, Path scene, List<String> jvm, String name) throws IOException, InterruptedException {
        Path png = dir.resolve(name + ".png");
        Cli.Run run = Cli.finished(dir, Cli.startJava(dir, jvm, scene.toString(), "--width=120", "--threads=2",
                "--output=" + png));
        assertThat(run.exitCode()).as("exit code; stderr: %s", run.err()).isZero();
        assertThat(run.out()).as("the walk named in the summary")
                .contains(switch (name) {
                    case "vector" -> "-wide vector walk";
                    case "scalar" -> "scalar walk (-Draytracer.simd=false)";
                    default -> " walk";
                });
        return Files.readAllBytes(png);
    }

    /**
     * A sphere of radius 10 with bumps, 250 rings × 200 segments = 99,600 triangles (fans at the
     * poles give slivers, the bumps varied sizes), as an OBJ file, and a lit scene around it.
     */
    private static Path bumpySphere(Path dir) throws IOException {
        int rings = 250, segments = 200;
        try (Writer obj = Files.newBufferedWriter(dir.resolve("bumpy.obj"))) {
            for (int i = 0; i <= rings; ++i)
                for (int j = 0; j < segments; ++j) {
                    double theta = Math.PI * i / rings, phi = 2 * Math.PI * j / segments;
                    double r = 10 * (1 + 0.05 * Math.sin(7 * theta) * Math.cos(5 * phi) + 0.02 * Math.sin(31 * phi + 3 * theta));
                    obj.write(String.format(Locale.ROOT, "v %.9f %.9f %.9f%n", r * Math.sin(theta) * Math.cos(phi),
                            r * Math.cos(theta), r * Math.sin(theta) * Math.sin(phi)));
                }
            for (int i = 0; i < rings; ++i)
                for (int j = 0; j < segments; ++j) {
                    int a = i * segments + j + 1, b = i * segments + (j + 1) % segments + 1;
                    int c = a + segments, d = b + segments;
                    if (i > 0) obj.write("f " + a + " " + b + " " + c + "\n");
                    if (i < rings - 1) obj.write("f " + b + " " + d + " " + c + "\n");
                }
        }
        Path scene = dir.resolve("bumpy.xml");
        Files.writeString(scene, """
                <scene name="bumpy" background-color="10 20 30">
                    <ambient-light color="255 255 255" ka="0.1"/>
                    <geometries>
                        <mesh file="bumpy.obj" emission="40 20 10">
                            <material kd="0.6" ks="0.3" shininess="40" kr="0.2"/>
                        </mesh>
                        <plane point="0 -12 0" normal="0 1 0"><material kd="0.5"/></plane>
                    </geometries>
                    <lights>
                        <point-light color="400 400 400" position="30 40 -30" radius="4"/>
                        <directional-light color="100 100 100" direction="-1 -1 1"/>
                    </lights>
                    <camera location="0 5 -40" target="0 0 0" up="0 1 0" vp-size="30 30" vp-distance="40"/>
                    <image name="bumpy" width="200" height="200"/>
                    <render shadow-samples="4" beam-size="2"/>
                </scene>
                """);
        return scene;
    }
}
