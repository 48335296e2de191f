package app.migrate;

import java.io.IOException;
import java.io.StringWriter;
import java.net.URI;
import java.util.ArrayList;
import java.util.List;

import javax.tools.Diagnostic;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.ToolProvider;

import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.tree.Tree;
import com.sun.source.util.JavacTask;
import com.sun.source.util.SourcePositions;
import com.sun.source.util.Trees;

/**
 * A source text as javac's own parser reads it (no compile: names are not resolved), with where
 * each part of it lies: what tells a name in the code from the same word in a string or a comment.
 *
 * <p>A text with parse errors (the unnamed variable {@code _} on an older JDK) is still read where
 * it parses; the compile that follows reports its errors and sets the file aside with them. Who
 * must not guess at a tree javac patched up (where a method ends, to cut it out) asks {@link #whole()}.
 *
 * @param errorLines the lines (1-based; -1 for an error javac placed nowhere) of the parser's errors
 */
record Parsed(CompilationUnitTree unit, SourcePositions positions, List<Long> errorLines) {
    Parsed {
        errorLines = List.copyOf(errorLines);
    }

    /**
     * @param name the file's name, for a message should javac fail
     * @throws MigrationException when this Java has no compiler, or javac fails on a text in memory
     */
    static Parsed of(String text, String name) throws MigrationException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null)
            throw new MigrationException("this Java (" + System.getProperty("java.home")
                    + ") has no compiler: run migrate with a JDK (17 or newer), as your IDE does");
        // The file's own name need not make a URI (a space, a Hebrew letter): parsing never looks at it.
        JavaFileObject source = new SimpleJavaFileObject(URI.create("string:///Source.java"), JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return text;
            }
        };
        try {
            // Errors are the compile's to report (see above): here only their lines are kept, for whole().
            List<Long> errorLines = new ArrayList<>();
            JavacTask task = (JavacTask) javac.getTask(new StringWriter(), null, diagnostic -> {
                if (diagnostic.getKind() == Diagnostic.Kind.ERROR) errorLines.add(diagnostic.getLineNumber());
            }, List.of("-proc:none"), null, List.of(source));
            CompilationUnitTree unit = task.parse().iterator().next();
            return new Parsed(unit, Trees.instance(task).getSourcePositions(), errorLines);
        } catch (IOException | IllegalStateException e) {
            throw new MigrationException("javac could not parse " + name + ": " + e.getMessage() + " (nothing was changed)", e);
        }
    }

    /** Whether javac parsed the text without an error: every tree stands where the text puts it. */
    boolean whole() {
        return errorLines.isEmpty();
    }

    long start(Tree t) {
        return positions.getStartPosition(unit, t);
    }

    long end(Tree t) {
        return positions.getEndPosition(unit, t);
    }

    /** The line (1-based) where {@code t} starts. */
    long line(Tree t) {
        return unit.getLineMap().getLineNumber(start(t));
    }
}
