package app.migrate;

import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Why a file does not compile against the library, in one line a student can act on: the missing
 * name and whose it is (a method of their own course class that the course API does not have, a
 * class of theirs that was set aside, a package that is not there), or the Java release it needs.
 * From javac's first error in the file; its message where nothing better can be said.
 */
final class Reasons {
    private static final Pattern SYMBOL = Pattern.compile("symbol:\\s+(method|variable|class|interface|enum|static)\\s+([^\\n]+)");
    private static final Pattern LOCATION = Pattern.compile(
            "location:\\s+(?:class|interface|enum|record|variable \\S+ of type|package)\\s+([\\w.$]+)");
    private static final Pattern PACKAGE_MISSING = Pattern.compile("package ([\\w.]+) does not exist");
    /** {@code o instanceof Point(double x, …)} or {@code case Point(…)}: a record pattern. */
    private static final Pattern RECORD_PATTERN = Pattern.compile("(\\binstanceof|\\bcase)\\s+[\\w.<>]+\\s*\\(");
    /** javac's "cannot be applied": the library's method or constructor, what it takes, what the call gave. */
    private static final Pattern CANT_APPLY = Pattern.compile("(method|constructor) (\\w+) in (?:class|interface|enum|record)"
            + " ([\\w.$]+) cannot be applied to given types;\\s*required: ([^\\n]*?)\\s*found:\\s*([^\\n]*)");
    /** javac's "cannot override": the student's method and class, the library's class, and why. */
    private static final Pattern CANT_OVERRIDE = Pattern.compile(
            "(\\w+)\\([^)]*\\) in ([\\w.$]+) cannot (?:override|implement) \\w+\\([^)]*\\) in ([\\w.$]+)\\s+([^\\n]+)");
    /** The method an {@code @Override} stands on: its name, before its parameters. */
    private static final Pattern DECLARED = Pattern.compile("(\\w+)\\s*\\(");
    /** javac's "no suitable method": the call, with the types it gave. */
    private static final Pattern NO_SUITABLE = Pattern.compile("no suitable (method|constructor) found for (\\w+)\\(([^)]*)\\)"
            + "(?:\\s*(?:method|constructor) ([\\w.$]+?)\\.\\w+\\()?");
    private static final Pattern SOURCE_LEVEL = Pattern.compile("use --?(?:source|release) (\\d+) or higher");
    /** The API of Java 21's sequenced collections, which course code of 2025–26 uses on lists. */
    private static final Set<String> SEQUENCED = Set.of("getFirst()", "getLast()", "removeFirst()", "removeLast()",
            "reversed()");

    /** The student's own course classes by simple name: their text, to tell their own methods. */
    private final Map<String, String> ownCourseClasses;
    /** Classes set aside (simple name → why), which files that use them cannot reach. */
    private final Map<String, String> setAside;
    /** The release the compile ran at: this JDK's newest. */
    private final int jdk;

    Reasons(Map<String, String> ownCourseClasses, Map<String, String> setAside, int jdk) {
        this.ownCourseClasses = ownCourseClasses;
        this.setAside = setAside;
        this.jdk = jdk;
    }

    /**
     * The release a compile error asks for, when it is one of a newer Java (0 otherwise): the
     * unnamed {@code _} (22), a language feature javac names with its release, the sequenced
     * collections (21).
     */
    static int releaseNeeded(Javac.Problem p) {
        String code = p.code();
        if (code.contains("underscore") || p.message().contains("unnamed")) return 22;
        Matcher m = SOURCE_LEVEL.matcher(p.message());
        if (m.find()) return Integer.parseInt(m.group(1));
        // Java 17's javac does not know record patterns (21) and reads one as a syntax error;
        // it knows switch patterns only as a preview.
        if (code.startsWith("compiler.err.preview.feature.disabled") || code.equals("compiler.err.enum.label.must.be.unqualified.enum"))
            return 21;
        if (code.startsWith("compiler.err.expected") || code.startsWith("compiler.err.illegal.start")) {
            String line = p.sourceLine();
            if (RECORD_PATTERN.matcher(line).find()) return 21;
        }
        if (code.startsWith("compiler.err.cant.resolve")) {
            Matcher s = SYMBOL.matcher(p.message());
            if (s.find() && SEQUENCED.contains(s.group(2).trim())) return 21;
        }
        return 0;
    }

    /**
     * The one-line reason, without the file and line (the caller puts them first).
     *
     * @param test whether the file is a test (the advice differs: port the test, or port the class)
     */
    String explain(Javac.Problem p, boolean test) {
        int release = releaseNeeded(p);
        if (release > jdk)
            return "needs Java " + release + " (" + feature(p) + "), and this JDK is " + jdk
                    + ": run migrate with JDK " + release + " or newer, or port it";
        String overload = overload(p, test);
        if (overload != null) return overload;
        String override = override(p, test);
        if (override != null) return override;
        Matcher pkg = PACKAGE_MISSING.matcher(p.message());
        if (pkg.find()) return "package " + pkg.group(1) + " is not in the build (neither the library's nor yours)";
        if (p.code().startsWith("compiler.err.cant.resolve")) {
            Matcher s = SYMBOL.matcher(p.message());
            Matcher l = LOCATION.matcher(p.message());
            if (s.find()) {
                String kind = s.group(1), name = s.group(2).trim();
                String owner = l.find() ? simple(l.group(1)) : null;
                if ((kind.equals("class") || kind.equals("interface") || kind.equals("enum")) && setAside.containsKey(name))
                    return name + " is your own class, set aside: " + setAside.get(name);
                String shown = owner == null ? name : owner + "." + name;
                String bare = name.replaceAll("\\(.*", "");
                if (owner != null && declares(ownText(owner), bare))
                    return shown + " is your own " + (kind.equals("method") ? "method" : "name")
                            + " (not in the course API): port " + (test ? "the test" : "it") + " or keep it aside";
                // Inherited (Triangle.createBoundingBox from the student's Polygon) or called
                // unqualified in a subclass: the course class that declares it.
                String declaring = ownCourseClasses.entrySet().stream().filter(e -> declares(e.getValue(), bare))
                        .map(Map.Entry::getKey).findFirst().orElse(null);
                if (declaring != null && !kind.equals("class"))
                    return shown + " is your own " + (kind.equals("method") ? "method" : "name") + " (of your " + declaring
                            + ", not in the course API): port " + (test ? "the test" : "it") + " or keep it aside";
                if (owner == null && kind.equals("class"))
                    return "class " + name + " is not in the build (neither the library's nor yours)";
                return shown + " is not in the library (nor in your course classes)";
            }
        }
        return Javac.oneLine(p.message());
    }

    /**
     * A call with arguments the library's method or constructor does not take: the student's own
     * overload when their course class declares that name ({@code Camera.renderImage(int) is your
     * own overload}), else what the library takes. Null for another error.
     */
    private String overload(Javac.Problem p, boolean test) {
        String owner, name, found, required = null;
        Matcher a = CANT_APPLY.matcher(p.message());
        Matcher n = NO_SUITABLE.matcher(p.message());
        if (a.find()) {
            owner = simple(a.group(3));
            name = a.group(2);
            required = a.group(4).trim();
            found = a.group(5).trim();
        } else if (n.find()) {
            name = n.group(2);
            found = n.group(3).trim();
            owner = n.group(4) != null ? simple(n.group(4)) : name;
        } else {
            return null;
        }
        boolean constructor = name.equals(owner);
        String call = owner + (constructor ? "" : "." + name) + "(" + shortTypes(found) + ")";
        String takes = required == null ? "" : "; the library's takes " + (required.equals("no arguments") ? "no arguments"
                : "(" + shortTypes(required) + ")");
        if (declares(ownText(owner), name) || (constructor && ownText(owner) != null))
            return call + " is your own overload (not in the course API" + takes + "): port " + (test ? "the test" : "it")
                    + " or keep it aside";
        return call + " is not in the library (nor in your course classes" + takes + ")";
    }

    /**
     * A method of the student's that the library's classes do not let it override: one of the
     * course API's (final there, or of another return type), or one of the library's insides a
     * course class of it inherits (their BVH's {@code getBoundingBox()}), which is named as such
     * rather than by the internal class; or an {@code @Override} of a method only their own course
     * class had. Null for another error.
     */
    private String override(Javac.Problem p, boolean test) {
        String advice = ": port " + (test ? "the test" : "it") + " or keep it aside";
        Matcher m = CANT_OVERRIDE.matcher(p.message());
        if (m.find()) {
            String mine = simple(m.group(2)) + "." + m.group(1) + "()", theirs = m.group(3);
            String why = shortTypes(m.group(4).trim());
            if (Catalog.isCourseClass(theirs))
                return mine + " cannot override the library's " + simple(theirs) + "." + m.group(1) + "() (" + why + ")" + advice;
            return mine + " clashes with a method of that name inside the library, which its course classes inherit (" + why
                    + "): rename yours" + (test ? ", or port the test" : "");
        }
        if (p.code().equals("compiler.err.method.does.not.override.superclass")) {
            Matcher d = DECLARED.matcher(p.sourceText(3).replaceAll("@\\w+(\\([^)]*\\))?", ""));
            String name = d.find() ? d.group(1) + "()" : "a method";
            return name + " is marked @Override, but nothing in the library has it to override (it overrode one of your own"
                    + " course classes)" + advice;
        }
        return null;
    }

    /** {@code java.util.List<primitives.Point>,int} → {@code List<Point>, int}. */
    private static String shortTypes(String types) {
        return types.replaceAll("\\b(?:[a-z]\\w*\\.)+([A-Z])", "$1").replaceAll("\\s*,\\s*", ", ");
    }

    /** The text of the student's course class of this simple name, nested ones ({@code Builder}) included. */
    private String ownText(String simpleName) {
        String top = ownCourseClasses.get(simpleName);
        if (top != null) return top;
        Pattern nested = Pattern.compile("\\b(class|interface|record|enum)\\s+" + Pattern.quote(simpleName) + "\\b");
        return ownCourseClasses.values().stream().filter(t -> nested.matcher(t).find()).findFirst().orElse(null);
    }

    private static String feature(Javac.Problem p) {
        if (p.code().contains("underscore") || p.message().contains("unnamed")) return "the unnamed variable _";
        if (RECORD_PATTERN.matcher(p.sourceLine()).find()) return "a record pattern";
        if (p.message().contains("getFirst") || p.message().contains("getLast")) return "List.getFirst/getLast";
        String first = p.message().lines().findFirst().orElse("").trim();
        return first.length() > 80 ? first.substring(0, 77) + "..." : first;
    }

    /** {@code java.util.List<primitives.Point>} → {@code List}. */
    private static String simple(String type) {
        String t = type.replaceAll("<.*", "");
        return t.substring(t.lastIndexOf('.') + 1);
    }

    /** Whether a class's text declares a method or field of this name (a declaration, not a call). */
    private static boolean declares(String text, String name) {
        if (text == null) return false;
        Pattern declaration = Pattern.compile("(?m)^[\\t ]*(?:(?:public|protected|private|static|final|abstract|default"
                + "|synchronized)\\s+)*[\\w.<>\\[\\], ?]+\\s+" + Pattern.quote(name) + "\\s*[(=;]");
        return declaration.matcher(text).find();
    }
}
