package app.migrate;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.tree.ExpressionTree;
import com.sun.source.tree.IdentifierTree;
import com.sun.source.tree.ImportTree;
import com.sun.source.tree.MemberSelectTree;
import com.sun.source.util.TreeScanner;

/**
 * A kept source pointed at the library: 2025–26's {@code geometries.api/impl} and
 * {@code lighting.api/impl} folded, and relocated course classes named as the library's.
 *
 * <p>The file is read by javac's own parser, and only names change: a package or import line, a
 * qualified name in the code. A string literal or a comment that spells the old name stays as the
 * student wrote it (it may be a message, or a note about the old layout); a regular expression over
 * the text could not tell them apart.
 */
final class SourceRewrite {
    private SourceRewrite() {
    }

    /** The file rewritten, and its new place (its package's folder, where its package changed). */
    static Kept kept(SourceFile f, Map<String, String> relocated) throws MigrationException {
        String text = rewrite(f.text(), f.path().toString(), relocated);
        Path target = f.path();
        String pkg = Catalog.libraryPackage(f.packageName());
        if (!pkg.equals(f.packageName()) && f.path().getParent().equals(f.root().resolve(f.packageName().replace('.', '/')))) {
            Path moved = f.root().resolve(pkg.replace('.', '/')).resolve(f.path().getFileName());
            if (!Files.exists(moved)) target = moved;
        }
        return new Kept(f, text, target);
    }

    /** The 2025–26 packages folded in {@code text}: {@code geometries.api.Intersectable} → {@code geometries.Intersectable}. */
    static String fold(String text) throws MigrationException {
        return rewrite(text, "Source.java", Map.of());
    }

    /**
     * Folds the 2025–26 packages, and names each relocated course class ({@code lighting.Material},
     * by its library name {@code primitives.Material}) as the library's: {@code import
     * lighting.Material;} becomes {@code import primitives.Material;}, and so does a qualified use;
     * a file that reached the class unqualified (in its package, or through {@code import
     * lighting.*;}) gets the library's import after its package line.
     *
     * @param name      the file's name, for a message should javac fail
     * @param relocated course classes kept in another course package → the library's name for them
     */
    static String rewrite(String text, String name, Map<String, String> relocated) throws MigrationException {
        Parsed parsed = Parsed.of(text, name);
        List<Edit> edits = new ArrayList<>();
        new Names(parsed, relocated, edits).scan(parsed.unit(), null);
        imports(parsed, text, relocated, edits);
        edits.sort(Comparator.comparingLong(Edit::start).reversed());
        StringBuilder out = new StringBuilder(text);
        for (Edit e : edits)
            if (e.start() >= 0 && e.end() >= e.start()) // a part javac could not place (a parse error there) stays as written
                out.replace((int) e.start(), (int) e.end(), e.with());
        return out.toString();
    }

    /** {@code text} from {@code start} to {@code end} becomes {@code with}. */
    private record Edit(long start, long end, String with) {
    }

    /** The dotted name an expression spells ({@code geometries.api.Intersectable}), or null when it is no plain name. */
    private static String dotted(ExpressionTree t) {
        if (t instanceof IdentifierTree id) return id.getName().toString();
        if (t instanceof MemberSelectTree s) {
            String left = dotted(s.getExpression());
            return left == null ? null : left + "." + s.getIdentifier();
        }
        return null;
    }

    /** The qualified names: a 2025–26 package folded, a relocated class named as the library's. */
    private static final class Names extends TreeScanner<Void, Void> {
        private final Parsed parsed;
        private final Map<String, String> relocated;
        private final List<Edit> edits;

        Names(Parsed parsed, Map<String, String> relocated, List<Edit> edits) {
            this.parsed = parsed;
            this.relocated = relocated;
            this.edits = edits;
        }

        @Override
        public Void visitMemberSelect(MemberSelectTree node, Void unused) {
            String name = dotted(node);
            if (name != null) {
                String folded = Catalog.libraryName(name);
                for (Map.Entry<String, String> r : relocated.entrySet())
                    if (folded.equals(Catalog.libraryName(r.getKey()))) {
                        edits.add(new Edit(parsed.start(node), parsed.end(node), r.getValue()));
                        return null;
                    }
                if (Catalog.isFolded(name)) {
                    // Only ".api" or ".impl" goes: the first name stays as written, spacing and all.
                    edits.add(new Edit(parsed.end(node.getExpression()), parsed.end(node), ""));
                    return null;
                }
            }
            return super.visitMemberSelect(node, unused);
        }
    }

    /** The library's import for each relocated class the file names unqualified, after its package line. */
    private static void imports(Parsed parsed, String text, Map<String, String> relocated, List<Edit> edits) {
        CompilationUnitTree unit = parsed.unit();
        // A name javac could not parse (null) is no package or import to match: the compile names its error.
        String declared = unit.getPackageName() == null ? null : dotted(unit.getPackageName());
        String pkg = declared == null ? "" : Catalog.libraryPackage(declared);
        List<String> imported = new ArrayList<>();
        for (ImportTree i : unit.getImports()) {
            String name = i.getQualifiedIdentifier() instanceof ExpressionTree e ? dotted(e) : null;
            if (!i.isStatic() && name != null) imported.add(Catalog.libraryName(name));
        }
        List<String> simpleNames = new ArrayList<>();
        new TreeScanner<Void, Void>() {
            @Override
            public Void visitIdentifier(IdentifierTree node, Void unused) {
                simpleNames.add(node.getName().toString());
                return null;
            }
        }.scan(unit.getTypeDecls(), null);
        long at = 0;
        if (unit.getPackage() != null) {
            int nl = text.indexOf('\n', (int) parsed.end(unit.getPackage()));
            at = nl < 0 ? text.length() : nl + 1;
        }
        StringBuilder lines = new StringBuilder();
        for (Map.Entry<String, String> r : relocated.entrySet()) {
            String from = Catalog.libraryName(r.getKey()), to = r.getValue();
            String fromPkg = from.substring(0, from.lastIndexOf('.')), simple = from.substring(from.lastIndexOf('.') + 1);
            boolean unqualified = pkg.equals(fromPkg) || imported.contains(fromPkg + ".*");
            if (unqualified && simpleNames.contains(simple) && !imported.contains(to) && !imported.contains(from))
                lines.append("import ").append(to).append(";\n");
        }
        if (lines.length() > 0) edits.add(new Edit(at, at, lines.toString()));
    }
}
