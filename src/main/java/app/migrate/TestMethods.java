package app.migrate;

import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Set;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import com.sun.source.tree.AnnotationTree;
import com.sun.source.tree.AssignmentTree;
import com.sun.source.tree.ClassTree;
import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.tree.ExpressionTree;
import com.sun.source.tree.IdentifierTree;
import com.sun.source.tree.LineMap;
import com.sun.source.tree.LiteralTree;
import com.sun.source.tree.MemberReferenceTree;
import com.sun.source.tree.MemberSelectTree;
import com.sun.source.tree.MethodInvocationTree;
import com.sun.source.tree.MethodTree;
import com.sun.source.tree.NewArrayTree;
import com.sun.source.tree.Tree;
import com.sun.source.util.JavacTask;
import com.sun.source.util.SourcePositions;
import com.sun.source.util.TreeScanner;
import com.sun.source.util.Trees;

/**
 * The test methods of a JUnit test file that javac rejects, taken out of its text one by one, so
 * that the file's other tests still build and run. Only javac's parser reads the file (no class
 * path, nothing written): methods, calls and annotations are known from its tree, never from the
 * text, so a string literal or a comment that looks like code changes nothing.
 */
final class TestMethods {
    /** A test file with some of its methods taken out. */
    record Trimmed(String text, List<String> removed) {
        Trimmed {
            Objects.requireNonNull(text, "text");
            removed = List.copyOf(removed);
        }
    }

    /** Annotations that make a method a test JUnit runs (JUnit 4's {@code @Test} has the same simple name). */
    private static final Set<String> TESTS = Set.of("Test", "ParameterizedTest", "RepeatedTest", "TestFactory");
    /**
     * Methods JUnit calls around the tests, and overrides: taking one out would not break the
     * build but would silently change what the remaining tests do.
     */
    private static final Set<String> KEPT = Set.of("BeforeEach", "AfterEach", "BeforeAll", "AfterAll", "Before",
            "After", "BeforeClass", "AfterClass", "Override");
    private static final String BOM = "\uFEFF";

    private TestMethods() {
    }

    /** A method that may be taken out, and the text its removal replaces: {@code [start, end)}. */
    private record Candidate(MethodTree tree, String name, long treeStart, int start, int end,
            String indent, String lineBreak, boolean test, boolean removable) {
    }

    /**
     * @param text          the test file's source
     * @param errorLines    the 1-based lines javac reported errors on
     * @param reasonComment why, said in each left-out method's place (line breaks become spaces)
     * @return the text without each method (of any top-level or nested class) whose span holds an
     *         error line, each replaced by one comment line; {@code null} when any error line lies
     *         outside a method that can be removed (an import, a field, a class header, an
     *         initializer, a constructor, a lifecycle method or an override), when a remaining part
     *         of the file calls a removed method or names it in {@code @MethodSource}, when the file
     *         does not parse, or when it would keep no test method
     * @throws IllegalStateException when this Java has no compiler (a JRE)
     */
    static Trimmed without(String text, Collection<Long> errorLines, String reasonComment) {
        Objects.requireNonNull(text, "text");
        Objects.requireNonNull(errorLines, "errorLines");
        Objects.requireNonNull(reasonComment, "reasonComment");
        // javac rejects a byte order mark as an illegal character; a space of the same length keeps every offset.
        String source = text.startsWith(BOM) ? " " + text.substring(1) : text;
        Parsed parsed = parse(source);
        if (parsed == null) return null;

        List<Candidate> candidates = parsed.candidates(source);
        // No method, no test to keep; and javac's line map of an empty file has no line 1 to look up.
        if (candidates.isEmpty()) return null;
        Set<Candidate> hit = new HashSet<>();
        for (Long line : errorLines) {
            Objects.requireNonNull(line, "an error line is null");
            Candidate owner = parsed.owner(source, line, candidates);
            if (owner == null || !owner.removable()) return null;
            hit.add(owner);
        }
        List<Candidate> removed = candidates.stream().filter(hit::contains).toList();
        List<Candidate> kept = candidates.stream().filter(c -> !hit.contains(c)).toList();
        if (kept.stream().noneMatch(Candidate::test)) return null;
        if (parsed.stillUsed(removed, kept)) return null;

        String reason = oneLine(reasonComment);
        StringBuilder out = new StringBuilder(text.length());
        int from = 0;
        for (Candidate c : removed) {
            out.append(text, from, c.start()).append(c.indent()).append("// raytracer migrate: ").append(c.name())
                    .append("() left out: ").append(reason).append(c.lineBreak());
            from = c.end();
        }
        out.append(text, from, text.length());
        return new Trimmed(out.toString(), removed.stream().map(Candidate::name).toList());
    }

    /**
     * The reason as one comment line: no line break, and no backslash that javac would read as the
     * start of a Unicode escape (javac reads escapes before comments: a backslash and a {@code u}
     * in a Windows folder name is an illegal escape even in a comment, and the escape of a line
     * feed would end the comment).
     */
    private static String oneLine(String reason) {
        String flat = reason.replace("\r\n", " ").replace('\r', ' ').replace('\n', ' ');
        StringBuilder out = new StringBuilder(flat.length());
        int backslashes = 0;
        for (int i = 0; i < flat.length(); i++) {
            char c = flat.charAt(i);
            // A run of backslashes before 'u' starts an escape when its length is odd: one more makes it even.
            if (c == 'u' && backslashes % 2 == 1) out.append('\\');
            backslashes = c == '\\' ? backslashes + 1 : 0;
            out.append(c);
        }
        return out.toString();
    }

    /** The parsed file with its positions; {@code null} when javac reports a syntax error. */
    private static Parsed parse(String source) {
        JavaCompiler compiler = ToolProvider.getSystemJavaCompiler();
        if (compiler == null)
            throw new IllegalStateException("this Java (" + System.getProperty("java.home")
                    + ") has no compiler: run migrate with a JDK (17 or newer)");
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        JavaFileObject file = new SimpleJavaFileObject(URI.create("string:///TestFile.java"), JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return source;
            }
        };
        try (StandardJavaFileManager files = compiler.getStandardFileManager(diagnostics, Locale.ROOT, StandardCharsets.UTF_8)) {
            // -proc:none: parsing needs no annotation processor, and looking for one would search the class path.
            JavacTask task = (JavacTask) compiler.getTask(new StringWriter(), files, diagnostics, List.of("-proc:none"),
                    null, List.of(file));
            CompilationUnitTree unit = null;
            for (CompilationUnitTree u : task.parse()) unit = u;
            for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics())
                if (d.getKind() == Diagnostic.Kind.ERROR) return null;
            if (unit == null) throw new IllegalStateException("javac parsed the test file into no compilation unit");
            return new Parsed(unit, Trees.instance(task).getSourcePositions());
        } catch (IOException e) {
            throw new UncheckedIOException("javac failed to read the test file from memory or to close its file manager", e);
        }
    }

    private static final class Parsed {
        private final CompilationUnitTree unit;
        private final SourcePositions positions;
        private final LineMap lines;
        /** The end of every tree in the file, sorted: what precedes a method in its text is code up to the nearest. */
        private final long[] ends;

        Parsed(CompilationUnitTree unit, SourcePositions positions) {
            this.unit = unit;
            this.positions = positions;
            this.lines = unit.getLineMap();
            List<Long> all = new ArrayList<>();
            new TreeScanner<Void, Void>() {
                @Override
                public Void scan(Tree tree, Void p) {
                    if (tree != null) {
                        long end = positions.getEndPosition(unit, tree);
                        if (end >= 0) all.add(end);
                    }
                    return super.scan(tree, p);
                }
            }.scan(unit, null);
            ends = all.stream().mapToLong(Long::longValue).sorted().toArray();
        }

        private long start(Tree tree) {
            return positions.getStartPosition(unit, tree);
        }

        private long end(Tree tree) {
            return positions.getEndPosition(unit, tree);
        }

        /** The methods with a body of every top-level and member class, in file order. */
        List<Candidate> candidates(String source) {
            List<Candidate> found = new ArrayList<>();
            for (Tree type : unit.getTypeDecls()) collect(type, source, found);
            found.sort(Comparator.comparingLong(Candidate::treeStart));
            return found;
        }

        private void collect(Tree member, String source, List<Candidate> found) {
            if (member instanceof ClassTree type) {
                for (Tree m : type.getMembers()) collect(m, source, found);
            } else if (member instanceof MethodTree method && method.getBody() != null) {
                found.add(candidate(method, source));
            }
        }

        private Candidate candidate(MethodTree method, String source) {
            long treeStart = start(method);
            long modifiers = start(method.getModifiers());
            if (modifiers >= 0) treeStart = Math.min(treeStart, modifiers);
            long treeEnd = end(method);
            if (treeStart < 0 || treeEnd < 0)
                throw new IllegalStateException("javac gave no position for method " + method.getName());
            Set<String> annotations = new HashSet<>();
            for (AnnotationTree a : method.getModifiers().getAnnotations()) annotations.add(simpleName(a.getAnnotationType()));
            String name = method.getName().toString();
            boolean test = annotations.stream().anyMatch(TESTS::contains);
            // A constructor cannot go: the fields it sets would be left unset.
            boolean removable = !name.equals("<init>") && annotations.stream().noneMatch(KEPT::contains);

            Gap before = Gap.lex(source, previousEnd(treeStart), (int) treeStart);
            int methodLine = lineStart(source, (int) treeStart);
            int start;
            String indent;
            if (before.lastCode() > methodLine) {
                // Code before the method on its line: the method alone goes, the line's start stays.
                start = (int) treeStart;
                indent = "";
            } else {
                start = before.commentsAbove(source, methodLine);
                if (start < 0) {
                    // The comment that ends on the method's line began after code: keep it, and that line's start.
                    start = (int) treeStart;
                    indent = "";
                } else {
                    indent = leadingBlanks(source, methodLine);
                }
            }
            int end = (int) treeEnd;
            String lineBreak;
            int afterLine = restOfLineIsComment(source, end);
            if (afterLine < 0) {
                // Code follows the closing brace on its line: it starts a line of its own after the comment.
                lineBreak = lineBreakOf(source, methodLine);
            } else {
                lineBreak = source.substring(lineEnd(source, end), afterLine);
                end = afterLine;
            }
            return new Candidate(method, name, treeStart, start, end, indent, lineBreak, test, removable);
        }

        /** The end of the last tree that ends at or before {@code position} (0: none). */
        private int previousEnd(long position) {
            int i = Arrays.binarySearch(ends, position);
            if (i >= 0) {
                while (i + 1 < ends.length && ends[i + 1] == position) i++;
                return (int) ends[i];
            }
            int before = -i - 2;
            return before < 0 ? 0 : (int) ends[before];
        }

        /** The method whose removal takes {@code line} out whole; {@code null} when none does. */
        Candidate owner(String source, long line, List<Candidate> candidates) {
            long last = lines.getLineNumber(source.length());
            if (line < 1 || line > last) return null;
            int from = (int) lines.getStartPosition(line);
            int to = lineEnd(source, from);
            for (Candidate c : candidates)
                if (c.start() <= from && to <= c.end() && from < c.end()) return c;
            return null;
        }

        /**
         * Whether what stays names a removed helper: calls it, refers to it ({@code this::helper}) or
         * takes its arguments from it ({@code @MethodSource}). By name only: a call of another
         * object's method of the same name is taken as a use, which only errs toward leaving the
         * whole file out. Removed test methods are not looked for: JUnit calls them, the code does
         * not, and a test is often named as the method it tests ({@code add()} calling {@code v.add}).
         */
        boolean stillUsed(List<Candidate> removed, List<Candidate> kept) {
            Set<String> names = new HashSet<>();
            for (Candidate c : removed) if (!c.test()) names.add(c.name());
            if (names.isEmpty()) return false;
            boolean[] used = { false };
            new TreeScanner<Void, Void>() {
                @Override
                public Void visitMethod(MethodTree method, Void p) {
                    // The removed methods' own calls do not count: they go with them.
                    for (Candidate c : removed)
                        if (c.tree() == method) return null;
                    return super.visitMethod(method, p);
                }

                @Override
                public Void visitMethodInvocation(MethodInvocationTree call, Void p) {
                    if (names.contains(simpleName(call.getMethodSelect()))) used[0] = true;
                    return super.visitMethodInvocation(call, p);
                }

                @Override
                public Void visitMemberReference(MemberReferenceTree reference, Void p) {
                    if (names.contains(reference.getName().toString())) used[0] = true;
                    return super.visitMemberReference(reference, p);
                }
            }.scan(unit, null);
            for (Candidate c : kept)
                for (String source : methodSources(c)) if (names.contains(source)) used[0] = true;
            return used[0];
        }
    }

    /** The factory method names a test's {@code @MethodSource} gives (none given: the test's own name). */
    private static List<String> methodSources(Candidate test) {
        List<String> found = new ArrayList<>();
        for (AnnotationTree a : test.tree().getModifiers().getAnnotations()) {
            if (!simpleName(a.getAnnotationType()).equals("MethodSource")) continue;
            if (a.getArguments().isEmpty()) found.add(test.name());
            for (ExpressionTree argument : a.getArguments()) {
                ExpressionTree value = argument instanceof AssignmentTree assignment ? assignment.getExpression() : argument;
                List<? extends ExpressionTree> values = value instanceof NewArrayTree array && array.getInitializers() != null
                        ? array.getInitializers() : List.of(value);
                for (ExpressionTree v : values)
                    if (v instanceof LiteralTree literal && literal.getValue() instanceof String s) found.add(factoryName(s));
            }
        }
        return found;
    }

    /** {@code "com.x.Cases#vectors(int)"} → {@code vectors}. */
    private static String factoryName(String reference) {
        String name = reference.substring(reference.indexOf('#') + 1);
        int parameters = name.indexOf('(');
        return (parameters < 0 ? name : name.substring(0, parameters)).strip();
    }

    /** {@code Test} of {@code Test} and of {@code org.junit.Test}; {@code ""} for anything else. */
    private static String simpleName(Tree name) {
        if (name instanceof IdentifierTree id) return id.getName().toString();
        if (name instanceof MemberSelectTree select) return select.getIdentifier().toString();
        return "";
    }

    /**
     * The text between the end of the tree before a method and the method: code that has no tree of
     * its own ({@code {}, {@code ;}, {@code class Name}), blanks and comments. It holds no literal
     * (every literal is a tree), so here a {@code //} or a {@code /*} always starts a comment.
     *
     * @param comments [start, end) of each comment, in order
     * @param lastCode the end of the last code character (the gap's start if it has none)
     */
    private record Gap(List<int[]> comments, int lastCode) {
        static Gap lex(String source, int from, int to) {
            List<int[]> comments = new ArrayList<>();
            int lastCode = from;
            int i = from;
            while (i < to) {
                char c = source.charAt(i);
                if (source.startsWith("//", i)) {
                    int end = Math.min(lineEnd(source, i), to);
                    comments.add(new int[] { i, end });
                    i = end;
                } else if (source.startsWith("/*", i)) {
                    int close = source.indexOf("*/", i + 2);
                    if (close < 0 || close + 2 > to)
                        throw new IllegalStateException("a comment at offset " + i + " runs into the method at " + to);
                    comments.add(new int[] { i, close + 2 });
                    i = close + 2;
                } else {
                    if (!Character.isWhitespace(c)) lastCode = i + 1;
                    i++;
                }
            }
            return new Gap(comments, lastCode);
        }

        /**
         * Where the comments directly above the method's line begin (its Javadoc, {@code //} lines):
         * each on lines of its own, without a blank line between them, except that blank lines
         * between the method and its Javadoc do not detach it (javac gives it to the method all the
         * same). The method's line start when there are none; -1 when a comment that ends on the
         * method's line began after code (the line's start then belongs to that code).
         */
        int commentsAbove(String source, int methodLine) {
            int start = methodLine;
            for (int k = comments.size() - 1; k >= 0; k--) {
                int[] comment = comments.get(k);
                if (comment[0] < lastCode) break;
                if (comment[0] >= start) continue; // on a line already taken, before what follows it there
                int line = lineStart(source, comment[0]);
                if (comment[1] > start) {
                    // Begun above and ending on a line already taken: it cannot be cut in two.
                    if (line < lastCode) return -1;
                    start = line;
                    continue;
                }
                boolean javadoc = source.startsWith("/**", comment[0]) && !source.startsWith("/**/", comment[0]);
                int breaks = lineBreaks(source.substring(comment[1], start));
                if (breaks > 1 && !(javadoc && start == methodLine)) break;
                if (line < lastCode) break; // after code on its first line: a comment on that code
                start = line;
            }
            return start;
        }

        private static int lineBreaks(String s) {
            return (int) s.replace("\r\n", "\n").chars().filter(ch -> ch == '\n' || ch == '\r').count();
        }
    }

    /**
     * After a method's closing brace: the offset after the line break that ends its line when the
     * rest of the line is blanks and comments, the text's end when it ends there; -1 when code follows.
     */
    private static int restOfLineIsComment(String source, int from) {
        int i = from;
        while (i < source.length()) {
            char c = source.charAt(i);
            if (c == '\r') return source.startsWith("\r\n", i) ? i + 2 : i + 1;
            if (c == '\n') return i + 1;
            if (source.startsWith("//", i)) {
                i = lineEnd(source, i);
            } else if (source.startsWith("/*", i)) {
                int close = source.indexOf("*/", i + 2);
                // A comment going on past this line stays, with the code after it.
                if (close < 0 || lineEnd(source, i) < close) return -1;
                i = close + 2;
            } else if (c == ' ' || c == '\t' || c == '\f') {
                i++;
            } else {
                return -1;
            }
        }
        return source.length();
    }

    private static int lineStart(String source, int position) {
        int i = position;
        while (i > 0 && source.charAt(i - 1) != '\n' && source.charAt(i - 1) != '\r') i--;
        return i;
    }

    /** The offset of the line break that ends the line holding {@code position} (the text's length when none). */
    private static int lineEnd(String source, int position) {
        int i = position;
        while (i < source.length() && source.charAt(i) != '\n' && source.charAt(i) != '\r') i++;
        return i;
    }

    /** The line break ending the line at {@code lineStart}; the file's first, or {@code \n}, when it has none. */
    private static String lineBreakOf(String source, int lineStart) {
        int end = lineEnd(source, lineStart);
        if (end == source.length()) end = lineEnd(source, 0);
        if (end == source.length()) return "\n";
        return source.startsWith("\r\n", end) ? "\r\n" : source.substring(end, end + 1);
    }

    private static String leadingBlanks(String source, int lineStart) {
        int i = lineStart;
        while (i < source.length() && (source.charAt(i) == ' ' || source.charAt(i) == '\t')) i++;
        return source.substring(lineStart, i);
    }
}
