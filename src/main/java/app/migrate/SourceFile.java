package app.migrate;

import java.io.IOException;
import java.nio.charset.Charset;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * One {@code .java} file of a course project: where it is, the package it declares and whether it
 * is a test. A file is a test when it lies in a test folder or uses JUnit (course projects often
 * keep {@code unittests/} inside {@code src/}, the one folder the IDE compiles).
 *
 * @param path        the file
 * @param root        the source folder it belongs to (its package folders start there)
 * @param packageName the package it declares ({@code ""} for none)
 * @param simpleName  the file name without {@code .java}: its top-level class
 * @param test        whether it is a test
 * @param text        its content (course files are small: a few kilobytes)
 */
record SourceFile(Path path, Path root, String packageName, String simpleName, boolean test, String text) {
    /** {@code package a.b;} after any comments; the first one (a package line is unique). */
    static final Pattern PACKAGE = Pattern.compile("(?m)^\\s*package\\s+([\\w.]+)\\s*;");
    /** A JUnit import, static or not, of any JUnit generation (4's {@code org.junit.Test} too). */
    static final Pattern JUNIT = Pattern.compile("(?m)^\\s*import\\s+(static\\s+)?org\\.junit\\.");

    static SourceFile read(Path path, Path root, boolean inTestFolder, Charset encoding) throws IOException {
        String text = new String(Files.readAllBytes(path), encoding);
        Matcher m = PACKAGE.matcher(text);
        String pkg = m.find() ? m.group(1) : "";
        String name = path.getFileName().toString();
        return new SourceFile(path, root, pkg, name.substring(0, name.length() - ".java".length()),
                inTestFolder || JUNIT.matcher(text).find(), text);
    }

    /** The top-level class's binary name: {@code geometries.impl.Sphere}. */
    String className() {
        return packageName.isEmpty() ? simpleName : packageName + "." + simpleName;
    }

    /** The path from the project's folder, with {@code /}: how the summary and the pom name it. */
    String relative(Path projectDir) {
        return projectDir.relativize(path).toString().replace('\\', '/');
    }

    /** The path from its source folder, with {@code /}: how a pom's includes and excludes name it. */
    String inRoot() {
        return root.relativize(path).toString().replace('\\', '/');
    }
}
