package app.migrate;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;

import com.sun.source.tree.IdentifierTree;
import com.sun.source.tree.MemberSelectTree;
import com.sun.source.tree.Tree;
import com.sun.source.util.TreeScanner;

/**
 * Where a source names a class (its simple name as a name in the code, an import, a qualified
 * name), read by javac's parser: the same word in a string or a comment is no use of the class.
 */
final class JavaNames {
    private JavaNames() {
    }

    /**
     * @param name the file's name, for a message should javac fail
     * @return the lines (1-based, ascending) where one of {@code names} stands as a name
     */
    static List<Long> lines(String text, String name, Set<String> names) throws MigrationException {
        Parsed parsed = Parsed.of(text, name);
        Set<Long> lines = new TreeSet<>();
        new TreeScanner<Void, Void>() {
            @Override
            public Void visitIdentifier(IdentifierTree node, Void unused) {
                if (names.contains(node.getName().toString())) add(node);
                return null;
            }

            @Override
            public Void visitMemberSelect(MemberSelectTree node, Void unused) {
                if (names.contains(node.getIdentifier().toString())) add(node);
                return super.visitMemberSelect(node, unused);
            }

            private void add(Tree node) {
                // A qualified name starts where its first part does: the name itself ends it, perhaps on a later line.
                long at = node instanceof MemberSelectTree s ? parsed.end(s) - 1 : parsed.start(node);
                if (at >= 0) lines.add(parsed.unit().getLineMap().getLineNumber(at));
            }
        }.scan(parsed.unit(), null);
        return List.copyOf(lines);
    }

    /** The first line where {@code simple} stands as a name, 0 when nowhere. */
    static long firstLine(String text, String name, String simple) throws MigrationException {
        List<Long> lines = lines(text, name, Set.of(simple));
        return lines.isEmpty() ? 0 : lines.get(0);
    }
}
