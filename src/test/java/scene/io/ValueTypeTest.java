package scene.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import geometries.Sphere;
import primitives.Double3;

/** The number grammar of scene files: plain decimals, the same on every machine. */
class ValueTypeTest {
    @Nested
    @DisplayName("numbers")
    class Numbers {
        @ParameterizedTest(name = "\"{0}\" is {1}")
        @CsvSource(delimiter = '|', value = { "50|50", "-0.25|-0.25", "+3|3", "1e-6|0.000001", "2.5E3|2500", ".5|0.5",
                "5.|5", "'  7  '|7", "-0|0", "1e9|1e9", "-1e9|-1e9", "1e-300|1e-300" })
        void valid(String text, double expected) {
            assertThat(ValueType.number(text)).isEqualTo(expected);
        }

        @ParameterizedTest(name = "\"{0}\" is not a number")
        @ValueSource(strings = { "abc", "1,5", "0x10", "1d", "1f", "1.2.3", "--1", "1e", "e5", ".", "1 2", "٣" })
        void malformed(String text) {
            assertThatThrownBy(() -> ValueType.number(text)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage("'" + text + "' is not a number");
        }

        @ParameterizedTest(name = "\"{0}\" is not finite")
        @ValueSource(strings = { "NaN", "nan", "Infinity", "-Infinity", "+inf", "1e309", "-1e999" })
        void nonFinite(String text) {
            assertThatThrownBy(() -> ValueType.number(text)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageStartingWith("'" + text + "' is not a finite number");
        }

        @ParameterizedTest(name = "\"{0}\" is beyond the limit")
        @ValueSource(strings = { "1000000001", "-1e10", "1.7976931348623157e308" })
        void beyondTheLimit(String text) {
            assertThatThrownBy(() -> ValueType.number(text)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessage(text + " is larger than 1000000000 in magnitude (the limit)");
        }

        @ParameterizedTest(name = "\"{0}\" is too small for a size or a factor")
        @ValueSource(strings = { "1e-300", "9.9e-10" })
        void tooSmall(String text) {
            assertThatThrownBy(() -> ValueType.POSITIVE.parse(text)).hasMessageStartingWith(text + " is closer to 0 than 1e-9");
            assertThatThrownBy(() -> ValueType.NON_NEGATIVE.parse(text)).hasMessageStartingWith(text + " is closer to 0 than 1e-9");
            assertThat(ValueType.NON_NEGATIVE.parse("0")).isZero();
            assertThat(ValueType.POSITIVE.parse("1e-9")).isEqualTo(1e-9);
        }

        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = { "-0.1", "0.1 -22 0.3" })
        @DisplayName("a negative coefficient is refused (a fuzzing finding: ka=\"0.1 -22 0.3\" failed in AmbientLight)")
        void negativeCoefficient(String text) {
            assertThatThrownBy(() -> ValueType.COEFFICIENTS.parse(text)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageEndingWith(" is negative");
        }

        @Test
        @DisplayName("empty text")
        void empty() {
            assertThatThrownBy(() -> ValueType.number("  ")).hasMessage("the value is empty");
        }
    }

    @Nested
    @DisplayName("triples and coefficients")
    class Triples {
        @Test
        @DisplayName("any white space separates, including tabs and line breaks")
        void whiteSpace() {
            assertThat(ValueType.POINT.parse(" 1\t2\n 3 ")).isEqualTo(new primitives.Point(1, 2, 3));
        }

        @Test
        @DisplayName("a coefficient is one number or three, never two")
        void coefficients() {
            assertThat(ValueType.COEFFICIENTS.parse("0.5")).isEqualTo(new Double3(0.5));
            assertThat(ValueType.COEFFICIENTS.parse("0.1 0.2 0.3")).isEqualTo(new Double3(0.1, 0.2, 0.3));
            assertThatThrownBy(() -> ValueType.COEFFICIENTS.parse("0.1 0.2"))
                    .hasMessage("found 2 values where 1 or 3 are needed");
        }
    }

    @Nested
    @DisplayName("independent of the locale")
    class LocaleIndependence {
        @TempDir
        Path dir;

        @Test
        @DisplayName("under a locale with decimal commas, '2.5' is still 2.5 and '2,5' still wrong")
        void germanLocale() throws Exception {
            Path file = dir.resolve("decimals.xml");
            Files.writeString(file, "<scene><geometries><sphere center=\"0.5 -1.25 3e2\" radius=\"2.5\"/></geometries></scene>");
            Path comma = dir.resolve("comma.xml");
            Files.writeString(comma, "<scene><geometries><sphere center=\"0 0 0\" radius=\"2,5\"/></geometries></scene>");
            Locale saved = Locale.getDefault();
            try {
                Locale.setDefault(Locale.GERMANY);
                Sphere s = (Sphere) XmlSceneReader.read(file).scene().geometries.getItems().get(0);
                assertThat(s.getRadius()).isEqualTo(2.5);
                assertThat(s.getCenter()).isEqualTo(new primitives.Point(0.5, -1.25, 300));
                assertThatThrownBy(() -> XmlSceneReader.read(comma)).isInstanceOf(SceneFormatException.class)
                        .hasMessageContaining("'2,5' is not a number");
            } finally {
                Locale.setDefault(saved);
            }
        }

        @Test
        @DisplayName("the XML parser's own messages stay English under another locale")
        void parserMessages() throws Exception {
            Path file = dir.resolve("broken.xml");
            Files.writeString(file, "<scene>");
            Locale saved = Locale.getDefault();
            try {
                Locale.setDefault(Locale.GERMANY);
                assertThatThrownBy(() -> XmlSceneReader.read(file)).hasMessageContaining("malformed XML: XML document structures must start and end within the same entity");
            } finally {
                Locale.setDefault(saved);
            }
        }
    }
}
