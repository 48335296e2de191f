package scene.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The scanner of a scene file's numbers accepts exactly what the regular expressions the reader
 * used before accept: each expression here is the specification its method is held to.
 */
class NumberTextTest {
    private static final Pattern DECIMAL = Pattern.compile("[+-]?(?:\\d+(?:\\.\\d*)?|\\.\\d+)(?:[eE][+-]?\\d+)?");
    private static final Pattern INTEGER = Pattern.compile("[+-]?\\d+");
    private static final Pattern NON_FINITE = Pattern.compile("[+-]?(?:nan|inf|infinity)", Pattern.CASE_INSENSITIVE);
    private static final Pattern WHITE_SPACE = Pattern.compile("\\s+");

    /** Every character either grammar gives a meaning to, and a few that look like one: NBSP, an Arabic 3, an em space. */
    private static final String ALPHABET = "0123456789+-.eEnaNAifItyY \t\n\u000B\f\r\u00A0\u0663\u2003x,";
    /** The decimal grammar's own characters: every other text drawn from these alone, so that many are numbers. */
    private static final String NUMERIC = "0123456789+-.eE";

    @Nested
    class Examples {
        @ParameterizedTest(name = "\"{0}\"")
        @ValueSource(strings = { "0", "50", "-0.25", "+3", "1e-6", "2.5E3", ".5", "5.", "-0", "007", "1.e5", ".5e+2",
                "", "+", "-", ".", "+.", "e5", "1e", "1e+", "1.2.3", "--1", "+-1", "1d", "0x10", "1,5", " 1", "1 ",
                "\u0663", "1\u00A02", "NaN", "-inf", "+Infinity", "infinit", "nanx", "inF" })
        void eachMethodAgreesWithItsExpression(String text) {
            agree(text);
        }

        @Test
        void wordsBetweenRunsOfAsciiSpace() {
            assertThat(NumberText.words("75 127\t\t90")).containsExactly("75", "127", "90");
            assertThat(NumberText.words("1\r\n2\u000B3\f4")).containsExactly("1", "2", "3", "4");
            assertThat(NumberText.words("1\u00A02 3\u20034")).as("NBSP and an em space are not \\s")
                    .containsExactly("1\u00A02", "3\u20034");
            assertThat(NumberText.words("")).isEmpty();
            assertThat(NumberText.words("7")).containsExactly("7");
        }
    }

    @Test
    void agreesWithTheExpressionsOnRandomTexts() {
        Random random = new Random(20261130L);
        StringBuilder sb = new StringBuilder();
        int decimals = 0, integers = 0, multiWord = 0; // the texts must reach every method's "yes"
        for (int i = 0; i < 300_000; ++i) {
            sb.setLength(0);
            String from = i % 2 == 0 ? ALPHABET : NUMERIC;
            int length = random.nextInt(9);
            for (int k = 0; k < length; ++k) sb.append(from.charAt(random.nextInt(from.length())));
            String text = sb.toString();
            agree(text);
            if (NumberText.isDecimal(text)) ++decimals;
            if (NumberText.isInteger(text)) ++integers;
            if (NumberText.words(text.strip()).length > 1) ++multiWord;
        }
        assertThat(decimals).as("decimals among the texts").isGreaterThan(1_000);
        assertThat(integers).as("integers among the texts").isGreaterThan(1_000);
        assertThat(multiWord).as("lists of several words among the texts").isGreaterThan(1_000);
    }

    private static void agree(String text) {
        assertThat(NumberText.isDecimal(text)).as("decimal \"%s\"", text).isEqualTo(DECIMAL.matcher(text).matches());
        assertThat(NumberText.isInteger(text)).as("integer \"%s\"", text).isEqualTo(INTEGER.matcher(text).matches());
        assertThat(NumberText.isNonFiniteWord(text)).as("non-finite \"%s\"", text)
                .isEqualTo(NON_FINITE.matcher(text).matches());
        String stripped = text.strip();
        String[] expected = stripped.isEmpty() ? new String[0] : WHITE_SPACE.split(stripped);
        assertThat(NumberText.words(stripped)).as("words of \"%s\"", stripped).containsExactly(expected);
    }
}
