package scene.io;

import java.util.Arrays;
import java.util.Locale;
import java.util.function.Consumer;
import java.util.stream.Collectors;

import primitives.Color;
import primitives.Double3;
import primitives.Point;
import primitives.Vector;

/**
 * A kind of attribute value: what the reader expects (for messages) and how the text becomes a
 * value. Numbers are plain decimals ("50", "-0.25", "1e-6") parsed the same on every machine
 * whatever its locale; "NaN", "Infinity", hexadecimal or Java suffixes ("1d") are rejected, and so
 * is any number beyond {@link Limits#MAX_MAGNITUDE}; a positive size or distance, or a
 * non-negative factor other than 0, is at least {@link Limits#MIN_MAGNITUDE}. Triples are separated by white space, as in the course's
 * scene files ("75 127 90").
 *
 * @param expected what a valid value looks like, completing "expected …" in messages
 * @param parser   the conversion; throws IllegalArgumentException with the reason
 */
record ValueType<T>(String expected, Parser<T> parser) {
    /** A conversion from attribute text to a value. */
    @FunctionalInterface
    interface Parser<T> {
        /** @throws IllegalArgumentException saying what is wrong with {@code text} */
        T parse(String text);
    }

    static final ValueType<Double> NUMBER = new ValueType<>("a number", ValueType::number);
    /** Sizes, distances and exponents: at least {@link Limits#MIN_MAGNITUDE}. */
    static final ValueType<Double> POSITIVE = new ValueType<>("a positive number", text -> {
        double d = number(text);
        if (!(d > 0)) throw new IllegalArgumentException(text.strip() + " is not positive");
        return notTiny(text, d);
    });
    /** Attenuation factors, spreads, a light's radius, the aperture: 0 or at least {@link Limits#MIN_MAGNITUDE}. */
    static final ValueType<Double> NON_NEGATIVE = new ValueType<>("a number ≥ 0", text -> {
        double d = number(text);
        if (d < 0) throw new IllegalArgumentException(text.strip() + " is negative");
        return notTiny(text, d);
    });
    static final ValueType<Integer> INTEGER = new ValueType<>("an integer", ValueType::integer);
    static final ValueType<Integer> POSITIVE_INTEGER = new ValueType<>("an integer ≥ 1", text -> {
        int i = integer(text);
        if (i < 1) throw new IllegalArgumentException(text.strip() + " is less than 1");
        return i;
    });
    static final ValueType<Long> LONG = new ValueType<>("an integer", text -> {
        String t = text.strip();
        if (!NumberText.isInteger(t)) throw new IllegalArgumentException("'" + t + "' is not an integer");
        try {
            return Long.parseLong(t);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(t + " is too large", e);
        }
    });
    static final ValueType<Boolean> BOOLEAN = new ValueType<>("true or false", text -> switch (text.strip()) {
        case "true" -> true;
        case "false" -> false;
        default -> throw new IllegalArgumentException("'" + text.strip() + "' is not a boolean");
    });
    static final ValueType<String> TEXT = new ValueType<>("a non-blank text", text -> {
        if (text.isBlank()) throw new IllegalArgumentException("the value is blank");
        return text.strip();
    });
    static final ValueType<Point> POINT = new ValueType<>("a point \"x y z\"", text -> {
        double[] d = numbers(text, 3, 3);
        return new Point(d[0], d[1], d[2]);
    });
    static final ValueType<Vector> VECTOR = new ValueType<>("a non-zero vector \"x y z\"", text -> {
        double[] d = numbers(text, 3, 3);
        if (d[0] == 0 && d[1] == 0 && d[2] == 0) throw new IllegalArgumentException("the zero vector has no direction");
        return new Vector(d[0], d[1], d[2]);
    });
    static final ValueType<Color> COLOR = new ValueType<>("a colour \"r g b\" of numbers ≥ 0 (255 is full)", text -> {
        double[] d = numbers(text, 3, 3);
        for (double c : d)
            if (c < 0) throw new IllegalArgumentException("colour component " + format(c) + " is negative");
        return new Color(d[0], d[1], d[2]);
    });
    /**
     * A coefficient for all three channels ("0.5") or one per channel ("0.5 0.7 0.6"), never
     * negative: every coefficient of the format (ka, kd, ks, kt, kr) scales light.
     */
    static final ValueType<Double3> COEFFICIENTS = new ValueType<>("a number or a triple \"r g b\", each ≥ 0", text -> {
        double[] d = numbers(text, 1, 3);
        for (double c : d)
            if (c < 0) throw new IllegalArgumentException("coefficient " + format(c) + " is negative");
        return d.length == 1 ? new Double3(d[0]) : new Double3(d[0], d[1], d[2]);
    });
    /** Two positive numbers "width height", or one for a square. */
    static final ValueType<double[]> SIZE = new ValueType<>("\"width height\" or one number for a square, positive", text -> {
        double[] d = numbers(text, 1, 2);
        for (double v : d)
            if (!(v > 0)) throw new IllegalArgumentException(format(v) + " is not positive");
        return d.length == 1 ? new double[] { d[0], d[0] } : d;
    });
    /** Two integers ≥ 1 "columns rows", or one for a square grid. */
    static final ValueType<int[]> GRID = new ValueType<>("\"columns rows\" or one integer for a square grid, each ≥ 1", text -> {
        String[] tokens = tokens(text, 1, 2);
        int[] grid = new int[2];
        for (int i = 0; i < 2; ++i) {
            grid[i] = integer(tokens[Math.min(i, tokens.length - 1)]);
            if (grid[i] < 1) throw new IllegalArgumentException(grid[i] + " is less than 1");
        }
        return grid;
    });

    T parse(String text) {
        return parser.parse(text);
    }

    /**
     * This type narrowed by a check, typically the library's own validating setter, so that its
     * rule and its message are not repeated here.
     *
     * @param narrower what a valid value looks like now
     * @param check    throws IllegalArgumentException for a value it refuses
     */
    ValueType<T> narrowedBy(String narrower, Consumer<T> check) {
        return new ValueType<>(narrower, text -> {
            T value = parse(text);
            check.accept(value);
            return value;
        });
    }

    /** Enum constants by name, case-insensitive ("adaptive" or "ADAPTIVE"). */
    static <E extends Enum<E>> ValueType<E> enumeration(Class<E> type) {
        E[] constants = type.getEnumConstants();
        String names = Arrays.stream(constants).map(c -> c.name().toLowerCase(Locale.ROOT)).collect(Collectors.joining(", "));
        return new ValueType<>("one of: " + names, text -> {
            for (E c : constants)
                if (c.name().equalsIgnoreCase(text.strip())) return c;
            throw new IllegalArgumentException("'" + text.strip() + "' is not a known value");
        });
    }

    /** A strict decimal number, at most {@link Limits#MAX_MAGNITUDE} in magnitude. */
    static double number(String text) {
        String t = text.strip();
        if (t.isEmpty()) throw new IllegalArgumentException("the value is empty");
        if (!NumberText.isDecimal(t)) { // digits only: a non-finite word never matches it
            if (NumberText.isNonFiniteWord(t)) throw new IllegalArgumentException("'" + t + "' is not a finite number");
            throw new IllegalArgumentException("'" + t + "' is not a number");
        }
        double d = Double.parseDouble(t); // locale-independent by specification
        if (!Double.isFinite(d)) throw new IllegalArgumentException("'" + t + "' is not a finite number (too large)");
        if (Math.abs(d) > Limits.MAX_MAGNITUDE)
            throw new IllegalArgumentException(t + " is larger than " + format(Limits.MAX_MAGNITUDE)
                    + " in magnitude (the limit)");
        return d;
    }

    /**
     * A positive quantity below {@link Limits#MIN_MAGNITUDE} is lost in the precision of the
     * coordinates it is added to (a view plane 1e-300 away gives rays no direction), or overflows
     * when inverted (an attenuation 1 / kc).
     */
    private static double notTiny(String text, double d) {
        if (d != 0 && d < Limits.MIN_MAGNITUDE)
            throw new IllegalArgumentException(text.strip() + " is closer to 0 than 1e-9 (the limit; write 0 for none"
                    + " where 0 is allowed)");
        return d;
    }

    private static int integer(String text) {
        String t = text.strip();
        if (!NumberText.isInteger(t)) throw new IllegalArgumentException("'" + t + "' is not an integer");
        try {
            return Integer.parseInt(t);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(t + " is too large", e);
        }
    }

    /** Between {@code min} and {@code max} numbers separated by white space; min == max: exactly that many. */
    private static double[] numbers(String text, int min, int max) {
        String[] tokens = tokens(text, min, max);
        double[] d = new double[tokens.length];
        for (int i = 0; i < tokens.length; ++i) d[i] = number(tokens[i]);
        return d;
    }

    private static String[] tokens(String text, int min, int max) {
        String t = text.strip();
        String[] tokens = NumberText.words(t);
        if (tokens.length < min || tokens.length > max || (tokens.length > min && tokens.length < max))
            throw new IllegalArgumentException("found " + tokens.length + (tokens.length == 1 ? " value" : " values")
                    + " where " + (min == max ? String.valueOf(min) : min + " or " + max) + " are needed");
        return tokens;
    }

    /** A double as the user most likely wrote it: "50" rather than "50.0". */
    static String format(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? String.valueOf((long) d) : String.valueOf(d);
    }
}
