package scene.io;

import java.util.ArrayList;
import java.util.List;

/**
 * The written forms of a scene file's numbers, read character by character rather than with
 * {@code java.util.regex}: a scene of a few hundred objects has thousands of numbers, enough for
 * the optimizing compiler to compile the regex matcher while the render starts, on the one
 * compiler thread a two-core machine has, ahead of the render's own code (40-80 ms of that
 * thread at each launch of the Sunflow scene; BENCHMARKS.md, issue 50, twelfth session). Each
 * method accepts exactly what the regular expression in its comment accepts ({@code \d} is
 * {@code [0-9]} and {@code \s} is {@code [ \t\n\x0B\f\r]}, as in {@code java.util.regex} without
 * its Unicode flag); {@code NumberTextTest} holds them to those expressions.
 */
final class NumberText {
    private NumberText() {
    }

    /** @return whether {@code s} is {@code [+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?}, a plain decimal */
    static boolean isDecimal(String s) {
        int n = s.length();
        int i = afterSign(s, 0);
        int whole = digitsFrom(s, i);
        i += whole;
        int fraction = 0;
        if (i < n && s.charAt(i) == '.') {
            fraction = digitsFrom(s, i + 1);
            i += 1 + fraction;
        }
        if (whole == 0 && fraction == 0) return false;
        if (i < n && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
            int exponentAt = afterSign(s, i + 1);
            int exponent = digitsFrom(s, exponentAt);
            if (exponent == 0) return false;
            i = exponentAt + exponent;
        }
        return i == n;
    }

    /** @return whether {@code s} is {@code [+-]?\d+} */
    static boolean isInteger(String s) {
        int i = afterSign(s, 0);
        int digits = digitsFrom(s, i);
        return digits > 0 && i + digits == s.length();
    }

    /** @return whether {@code s} is {@code [+-]?(?:nan|inf|infinity)}, case aside: a non-finite word */
    static boolean isNonFiniteWord(String s) {
        String word = s.substring(afterSign(s, 0));
        return word.equalsIgnoreCase("nan") || word.equalsIgnoreCase("inf") || word.equalsIgnoreCase("infinity");
    }

    /**
     * @param s a text without white space at either end ({@link String#strip})
     * @return the words of {@code s} between runs of {@code \s}, as {@code s.split("\\s+")}; none when {@code s} is empty
     */
    static String[] words(String s) {
        List<String> words = new ArrayList<>(3);
        int n = s.length();
        for (int i = 0; i < n; ) {
            int end = i;
            while (end < n && !isSpace(s.charAt(end))) ++end;
            if (end > i) words.add(s.substring(i, end));
            i = end;
            while (i < n && isSpace(s.charAt(i))) ++i;
        }
        return words.toArray(new String[0]);
    }

    /** {@code \s}: the six ASCII white-space characters, not Unicode's others */
    private static boolean isSpace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\u000B' || c == '\f' || c == '\r';
    }

    private static int afterSign(String s, int i) {
        return i < s.length() && (s.charAt(i) == '+' || s.charAt(i) == '-') ? i + 1 : i;
    }

    /** @return how many of {@code [0-9]} follow from {@code i} */
    private static int digitsFrom(String s, int i) {
        int end = i;
        while (end < s.length() && s.charAt(end) >= '0' && s.charAt(end) <= '9') ++end;
        return end - i;
    }
}
