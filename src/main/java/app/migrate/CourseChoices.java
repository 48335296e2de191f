package app.migrate;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Where the student's own course classes chose otherwise than the library, at the points where
 * course years disagree and the library picked one (docs/student-guide.md, "Which course year?"). Read from the
 * classes before they move, so the student learns which of their tests will change and why
 * before a single test runs on the library.
 */
final class CourseChoices {
    /** One difference: what the student's code does, where, the library's choice, and the tests it touches. */
    record Choice(String what, String where, String library, List<String> tests) {
        String line() {
            String touched = tests.isEmpty() ? "no test of yours uses it"
                    : tests.size() + " test file" + (tests.size() == 1 ? "" : "s") + " will change: "
                            + String.join(", ", tests.subList(0, Math.min(5, tests.size())))
                            + (tests.size() > 5 ? ", ..." : "");
            return what + " (" + where + "); the library: " + library + "; " + touched;
        }
    }

    /**
     * @param sayUntouched whether the choice is named when no test touches it (false where most
     *                     students' classes make it and only the tests that rely on it matter)
     */
    private record Rule(String className, Pattern pattern, String what, String library, Predicate<String> touches,
            boolean sayUntouched) {
        Rule(String className, Pattern pattern, String what, String library, Predicate<String> touches) {
            this(className, pattern, what, library, touches, true);
        }
    }

    private static final Pattern QUERY_WITH_MAX = Pattern.compile(
            "\\b(findGeoIntersections|calculateIntersections|calcIntersections|findIntersections)(?:Helper)?\\s*\\([^;()]*(\\([^;()]*\\))?[^;()]*,");

    private static final List<Rule> RULES = List.of(
            new Rule("primitives.Vector",
                    Pattern.compile("\\bZ\\s*=\\s*new\\s+Vector\\s*\\(\\s*0(?:\\.0)?d?\\s*,\\s*0(?:\\.0)?d?\\s*,\\s*-\\s*1"),
                    "your Vector.Z is (0, 0, -1)",
                    "Vector.Z is +z (0, 0, 1), as AXIS_Z; renders looking along your -z come out blank",
                    text -> text.matches("(?s).*\\bVector\\.Z\\b.*")),
            new Rule("geometries.Cylinder",
                    // (double, Ray, double) with the height first: told by the names, the first
                    // a height (h, height, len…) or the last a radius (r, rad, radius…).
                    Pattern.compile("\\bCylinder\\s*\\(\\s*(?:final\\s+)?[dD]ouble\\s+(?:(?i:h|\\w*height\\w*|len\\w*)\\s*,"
                            + "\\s*(?:final\\s+)?Ray\\s+\\w+\\s*,\\s*(?:final\\s+)?[dD]ouble\\s+\\w+|\\w+\\s*,\\s*(?:final\\s+)?Ray"
                            + "\\s+\\w+\\s*,\\s*(?:final\\s+)?[dD]ouble\\s+(?i:r|rad\\w*|\\w*radius\\w*))\\s*\\)"),
                    "your Cylinder(height, axis, radius) takes the height first",
                    "Cylinder(radius, axis, height), radius first (Java cannot tell the two apart); swap the numbers or use Cylinder(height, radius, axis)",
                    text -> text.contains("new Cylinder(")),
            new Rule(null,
                    Pattern.compile("alignZero\\s*\\(\\s*\\w+\\s*-\\s*maxDistance\\s*\\)\\s*<\\s*0|\\b\\w+\\s*<\\s*maxDistance\\b|maxDistance\\s*>\\s*\\w+\\s*\\)"),
                    "your queries exclude a hit exactly at maxDistance",
                    "a hit exactly at maxDistance counts, in every year's query",
                    text -> QUERY_WITH_MAX.matcher(text).find()),
            new Rule("renderer.Camera",
                    // An assignment to the view direction within rotate's first lines: a turn of
                    // the direction (yaw), where the library rolls about it.
                    Pattern.compile("\\brotate\\s*\\(\\s*(?:final\\s+)?(?:double|int)\\s+\\w+\\s*\\)\\s*\\{(?s:.{0,1200}?)"
                            + "(?i:\\b_?(?:new)?v_?to\\w*)\\s*=(?!=)"),
                    "your Builder.rotate(degrees) turns the view direction (about the up vector)",
                    "rotate(degrees) rolls the camera about its view direction (right-hand rule; the direction stays)",
                    text -> text.matches("(?s).*\\.rotate\\s*\\(.*")),
            new Rule("renderer.Camera",
                    Pattern.compile("\\b(?:location|p0|position|cameraLocation|place)\\s*=\\s*(?:Point\\.ZERO|new\\s+Point\\s*\\(\\s*0(?:\\.0)?\\s*,\\s*0(?:\\.0)?\\s*,\\s*0(?:\\.0)?\\s*\\))\\s*;"),
                    "your camera defaults its location (to the origin)",
                    "build() without setLocation throws MissingResourceException",
                    CourseChoices::buildsWithoutLocation),
            new Rule("renderer.ImageWriter",
                    // The class never tests its name for blank: it writes "" as ".png".
                    Pattern.compile("(?s)\\A(?!.*\\b(?:isBlank|isEmpty|trim\\(\\)\\.length)\\s*\\()"),
                    "your ImageWriter takes a blank image name",
                    "a blank image name is refused (IllegalArgumentException: image name must not be blank)",
                    // Most students' writers take any name: said only where a test gives a blank one.
                    CourseChoices::namesImageBlank, false),
            new Rule("lighting.PointLight",
                    // A light of theirs that never refuses a point: it answers at its own position.
                    Pattern.compile("(?s)\\A(?!.*throw\\s+new\\s+IllegalArgumentException)"),
                    "your lights answer getL/getIntensity at their own position",
                    "a point at a light's position is refused (IllegalArgumentException: the direction from the light to it"
                            + " is undefined)",
                    CourseChoices::asksLightAtItsPosition, false));

    private static final Pattern LIGHT = Pattern.compile("\\bnew\\s+(?:PointLight|SpotLight)\\s*\\(");
    private static final Pattern LIGHT_QUERY = Pattern.compile("\\.(?:getL|getIntensity)\\s*\\(");

    /**
     * Whether a test asks a point or spot light about the very point it was built at: a
     * {@code getL}/{@code getIntensity} argument that is, word for word, an argument of a
     * {@code new PointLight(…)}/{@code new SpotLight(…)} of the file ({@code new Point(1, 2, 3)},
     * or a constant such as {@code POSITION}). A call inside {@code assertThrows} expects the refusal.
     */
    static boolean asksLightAtItsPosition(String text) {
        List<String> positions = new ArrayList<>();
        Matcher light = LIGHT.matcher(text);
        while (light.find()) positions.addAll(arguments(text, light.end()));
        if (positions.isEmpty()) return false;
        Matcher query = LIGHT_QUERY.matcher(text);
        while (query.find()) {
            List<String> asked = arguments(text, query.end());
            int statement = Math.max(text.lastIndexOf(';', query.start()), text.lastIndexOf('{', query.start()));
            if (asked.size() == 1 && positions.contains(asked.get(0))
                    && !text.substring(statement + 1, query.start()).contains("assertThrows"))
                return true;
        }
        return false;
    }

    /** The top-level arguments of the call whose {@code (} ends at {@code from}, whitespace squeezed. */
    private static List<String> arguments(String text, int from) {
        List<String> args = new ArrayList<>();
        int depth = 0, start = from;
        for (int i = from; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '(') depth++;
            else if (c == ')' && depth-- == 0) {
                args.add(text.substring(start, i).replaceAll("\\s+", " ").strip());
                break;
            } else if (c == ',' && depth == 0) {
                args.add(text.substring(start, i).replaceAll("\\s+", " ").strip());
                start = i + 1;
            }
        }
        return args;
    }

    /** A test that names an image "" (directly, or through a variable set to ""). */
    private static final Pattern BLANK_NAME = Pattern.compile("(?:ImageWriter|writeToImage)\\s*\\(\\s*\"\\s*\"|\\bString\\s+\\w+\\s*=\\s*\"\\s*\"\\s*;");
    private static final Pattern LOCATION = Pattern.compile("\\.(?:setLocation|setP0|setPosition|setCameraLocation)\\s*\\(");
    /** {@code = builder.set…(…).build()} or {@code builder.…build()}: the statement's first name. */
    private static final Pattern STATEMENT_START = Pattern.compile("(?:=|^|return)\\s*(\\w+)\\s*[.\\n]");

    static boolean namesImageBlank(String text) {
        return BLANK_NAME.matcher(text).find();
    }

    /**
     * Whether a test builds a camera with no location set on the way: a {@code build()} whose
     * statement sets none, where the builder it starts from (a field or variable of the file) was
     * declared without one too. Per statement, so a file that sets a location for one camera and
     * not for another touches the rule.
     */
    static boolean buildsWithoutLocation(String text) {
        if (!text.matches("(?s).*\\b(getBuilder|Camera\\.Builder)\\b.*")) return false;
        int at = 0;
        while ((at = text.indexOf(".build()", at)) >= 0) {
            int start = Math.max(Math.max(text.lastIndexOf(';', at), text.lastIndexOf('{', at)), text.lastIndexOf('}', at)) + 1;
            String statement = text.substring(start, at);
            at += ".build()".length();
            if (LOCATION.matcher(statement).find()) continue;
            Matcher first = STATEMENT_START.matcher(statement.strip());
            if (first.find() && !first.group(1).equals("Camera")) {
                Matcher declared = Pattern.compile("\\b" + Pattern.quote(first.group(1)) + "\\s*=([^;]*);").matcher(text);
                if (declared.find() && LOCATION.matcher(declared.group(1)).find()) continue;
            }
            return true;
        }
        return false;
    }

    private CourseChoices() {
    }

    /**
     * @param course the student's course classes that the library replaces
     * @param tests  the student's tests
     */
    static List<Choice> find(List<SourceFile> course, List<SourceFile> tests, Path projectDir) {
        List<Choice> found = new ArrayList<>();
        for (Rule rule : RULES) {
            for (SourceFile f : course) {
                if (rule.className != null && !Catalog.libraryName(f.className()).equals(rule.className)) continue;
                if (rule.className == null && !Catalog.libraryPackage(f.packageName()).equals("geometries")) continue;
                Matcher m = rule.pattern.matcher(f.text());
                if (!m.find()) continue;
                List<String> touched = tests.stream().filter(t -> rule.touches.test(t.text()))
                        .map(t -> t.path().getFileName().toString()).toList();
                if (touched.isEmpty() && !rule.sayUntouched) break;
                found.add(new Choice(rule.what, f.relative(projectDir) + ":" + line(f.text(), m.start()), rule.library, touched));
                break; // one line per choice: the first class that makes it
            }
        }
        return found;
    }

    private static long line(String text, int offset) {
        return text.substring(0, offset).chars().filter(c -> c == '\n').count() + 1;
    }
}
