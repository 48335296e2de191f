package app.migrate;

import static app.migrate.TextLines.leadingBlanks;
import static app.migrate.TextLines.lineBreakOf;
import static app.migrate.TextLines.lineEnd;
import static app.migrate.TextLines.lineStart;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import com.sun.source.tree.AnnotationTree;
import com.sun.source.tree.AssignmentTree;
import com.sun.source.tree.ClassTree;
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
import com.sun.source.util.TreeScanner;

/**
 * The methods of a test file as javac's parser bounds them, each widened to whole lines (its
 * Javadoc and comment lines above, the line break after it), and what names them. A method's
 * bounds, its annotations and the calls of it come from the tree, never from the text: a brace or
 * an {@code @Test} in a string, a character literal or a comment is inside some tree or between
 * trees, never taken for code. Only the gaps between trees are read as text, and they hold
 * nothing but code without a tree of its own, blanks and comments.
 */
final class MethodSpans {
    /** Annotations that make a method a test JUnit runs (JUnit 4's {@code @Test} has the same simple name). */
    private static final Set<String> TESTS = Set.of("Test", "ParameterizedTest", "RepeatedTest", "TestFactory");
    /**
     * Methods JUnit calls around the tests, and overrides: taking one out would not break the
     * build but would silently change what the remaining tests do.
     */
    private static final Set<String> KEPT = Set.of("BeforeEach", "AfterEach", "BeforeAll", "AfterAll", "Before",
            "After", "BeforeClass", "AfterClass", "Override");

    private final Parsed parsed;
    private final String source;
    private final LineMap lines;
    /** The end of every tree in the file, sorted: what precedes a method in its text is code up to the nearest. */
    private final long[] ends;

    /**
     * @param parsed {@code source} parsed whole ({@link Parsed#whole()}): the bounds of a tree javac
     *               patched up after an error are a guess
     * @throws IllegalArgumentException when it was not
     */
    MethodSpans(Parsed parsed, String source) {
        if (!parsed.whole())
            throw new IllegalArgumentException("javac's parser found errors on lines " + parsed.errorLines()
                    + ": method bounds would be guessed");
        this.parsed = parsed;
        this.source = source;
        this.lines = parsed.unit().getLineMap();
        List<Long> all = new ArrayList<>();
        new TreeScanner<Void, Void>() {
            @Override
            public Void scan(Tree tree, Void p) {
                if (tree != null) {
                    long end = parsed.end(tree);
                    if (end >= 0) all.add(end);
                }
                return super.scan(tree, p);
            }
        }.scan(parsed.unit(), null);
        ends = all.stream().mapToLong(Long::longValue).sorted().toArray();
    }

    /** The methods with a body of every top-level and member class, in file order. */
    List<MethodSpan> all() {
        List<MethodSpan> found = new ArrayList<>();
        for (Tree type : parsed.unit().getTypeDecls()) collect(type, found);
        found.sort(Comparator.comparingLong(MethodSpan::treeStart));
        return found;
    }

    private void collect(Tree member, List<MethodSpan> found) {
        if (member instanceof ClassTree type) {
            for (Tree m : type.getMembers()) collect(m, found);
        } else if (member instanceof MethodTree method && method.getBody() != null) {
            found.add(span(method));
        }
    }

    private MethodSpan span(MethodTree method) {
        long treeStart = parsed.start(method);
        long modifiers = parsed.start(method.getModifiers());
        if (modifiers >= 0) treeStart = Math.min(treeStart, modifiers);
        long treeEnd = parsed.end(method);
        if (treeStart < 0 || treeEnd < 0)
            throw new IllegalStateException("javac gave no position for method " + method.getName());
        Set<String> annotations = new HashSet<>();
        for (AnnotationTree a : method.getModifiers().getAnnotations()) annotations.add(simpleName(a.getAnnotationType()));
        String name = method.getName().toString();
        boolean test = annotations.stream().anyMatch(TESTS::contains);
        // A constructor cannot go: the fields it sets would be left unset.
        boolean removable = !name.equals("<init>") && annotations.stream().noneMatch(KEPT::contains);

        CommentGap before = CommentGap.lex(source, previousEnd(treeStart), (int) treeStart);
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
        int afterLine = restOfLineIsComment(end);
        if (afterLine < 0) {
            // Code follows the closing brace on its line: it starts a line of its own after the comment.
            lineBreak = lineBreakOf(source, methodLine);
        } else {
            lineBreak = source.substring(lineEnd(source, end), afterLine);
            end = afterLine;
        }
        return new MethodSpan(method, name, treeStart, start, end, indent, lineBreak, test, removable);
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

    /**
     * After a method's closing brace: the offset after the line break that ends its line when the
     * rest of the line is blanks and comments, the text's end when it ends there; -1 when code
     * follows. Text read up to the first code character only: no literal can come before it.
     */
    private int restOfLineIsComment(int from) {
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

    /** The method whose removal takes {@code line} out whole; {@code null} when none does. */
    MethodSpan owner(long line, List<MethodSpan> spans) {
        long last = lines.getLineNumber(source.length());
        if (line < 1 || line > last) return null;
        int from = (int) lines.getStartPosition(line);
        int to = lineEnd(source, from);
        for (MethodSpan s : spans)
            if (s.start() <= from && to <= s.end() && from < s.end()) return s;
        return null;
    }

    /**
     * Whether what stays names a removed helper: calls it, refers to it ({@code this::helper}) or
     * takes its arguments from it ({@code @MethodSource}). By name only: a call of another
     * object's method of the same name is taken as a use, which only errs toward leaving the
     * whole file out. Removed test methods are not looked for: JUnit calls them, the code does
     * not, and a test is often named as the method it tests ({@code add()} calling {@code v.add}).
     */
    boolean stillUsed(List<MethodSpan> removed, List<MethodSpan> kept) {
        Set<String> names = new HashSet<>();
        for (MethodSpan s : removed) if (!s.test()) names.add(s.name());
        if (names.isEmpty()) return false;
        boolean[] used = { false };
        new TreeScanner<Void, Void>() {
            @Override
            public Void visitMethod(MethodTree method, Void p) {
                // The removed methods' own calls do not count: they go with them.
                for (MethodSpan s : removed)
                    if (s.tree() == method) return null;
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
        }.scan(parsed.unit(), null);
        for (MethodSpan s : kept)
            for (String factory : methodSources(s)) if (names.contains(factory)) used[0] = true;
        return used[0];
    }

    /** The factory method names a test's {@code @MethodSource} gives (none given: the test's own name). */
    private static List<String> methodSources(MethodSpan test) {
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
}
