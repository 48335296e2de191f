package app.migrate;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A kept source pointed at the library: 2025–26's {@code geometries.api/impl} and
 * {@code lighting.api/impl} folded, and relocated course classes named as the library's.
 */
final class SourceRewrite {
    private SourceRewrite() {
    }

    /** The file rewritten, and its new place (its package's folder, where its package changed). */
    static Kept kept(SourceFile f, Map<String, String> relocated) throws MigrationException {
        String text = relocate(fold(f.text()), f.packageName(), relocated);
        Path target = f.path();
        String pkg = Catalog.libraryPackage(f.packageName());
        if (!pkg.equals(f.packageName()) && f.path().getParent().equals(f.root().resolve(f.packageName().replace('.', '/')))) {
            Path moved = f.root().resolve(pkg.replace('.', '/')).resolve(f.path().getFileName());
            if (!Files.exists(moved)) target = moved;
        }
        return new Kept(f, text, target);
    }

    static String fold(String text) {
        return text.replaceAll("(?m)^(\\s*(?:package|import)\\s+(?:static\\s+)?)(geometries|lighting)\\.(?:api|impl)\\s*;", "$1$2;")
                .replaceAll("\\b(geometries|lighting)\\.(?:api|impl)\\.", "$1.");
    }

    /**
     * {@code import lighting.Material;} becomes {@code import primitives.Material;} (and so does a
     * qualified use); a file that reached the class unqualified (in its package, or through
     * {@code import lighting.*;}) gets the library's import after its package line.
     */
    static String relocate(String text, String pkg, Map<String, String> relocated) {
        String t = text;
        for (Map.Entry<String, String> e : relocated.entrySet()) {
            String from = Catalog.libraryName(e.getKey()), to = e.getValue();
            String fromPkg = from.substring(0, from.lastIndexOf('.')), simple = from.substring(from.lastIndexOf('.') + 1);
            t = fold(t).replaceAll("\\b" + Pattern.quote(from) + "\\b", to);
            boolean unqualified = Catalog.libraryPackage(pkg).equals(fromPkg)
                    || Pattern.compile("(?m)^\\s*import\\s+" + Pattern.quote(fromPkg) + "\\.\\*\\s*;").matcher(t).find();
            if (!unqualified || !Pattern.compile("\\b" + Pattern.quote(simple) + "\\b").matcher(t).find()
                    || t.contains("import " + to + ";"))
                continue;
            Matcher p = Pattern.compile("(?m)^\\s*package\\s+[\\w.]+\\s*;[^\\n]*\\n").matcher(t);
            String line = "import " + to + ";\n";
            t = p.find() ? t.substring(0, p.end()) + line + t.substring(p.end()) : line + t;
        }
        return t;
    }
}
