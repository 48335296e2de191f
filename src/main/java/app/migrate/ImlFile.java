package app.migrate;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * IntelliJ's side of the migration, so the IDE project works without a re-import: the library jar
 * (from the local Maven repository, where {@code mvn install} put it) added to the module's
 * dependencies in its {@code .iml}, and the tests left out of the build kept out of the IDE's
 * compile too ({@code .idea/compiler.xml}, "Excludes"), where they would stop Build Project.
 * Both edits insert text and keep the rest of the file as it was.
 */
final class ImlFile {
    /** The module library's name: how the migration finds its own entry again. */
    static final String LIBRARY_NAME = "raytracer (added by raytracer migrate)";
    private static final Pattern ROOT_MANAGER = Pattern.compile("<component\\s+name=\"NewModuleRootManager\"[^>]*>");
    private static final Pattern COMPILER_CONFIGURATION = Pattern.compile("<component\\s+name=\"CompilerConfiguration\"[^>]*>");

    private ImlFile() {
    }

    /** The jar as IntelliJ names a file of the local Maven repository. */
    static String jarUrl(BuildPlan plan, String classifier) {
        String base = plan.groupId().replace('.', '/') + "/" + plan.artifactId() + "/" + plan.version() + "/"
                + plan.artifactId() + "-" + plan.version() + (classifier.isEmpty() ? "" : "-" + classifier) + ".jar";
        return "jar://$MAVEN_REPOSITORY$/" + base + "!/";
    }

    /**
     * @return the module file with the library among its dependencies (unchanged when it is there),
     *         or null when the file has no module root manager to add it to
     */
    static String addLibrary(String iml, BuildPlan plan) {
        if (iml.contains(LIBRARY_NAME)) return iml;
        Matcher m = ROOT_MANAGER.matcher(iml);
        if (!m.find()) return null;
        int end = iml.indexOf("</component>", m.end());
        if (end < 0) return null;
        String entry = "  <orderEntry type=\"module-library\">\n"
                + "      <library name=\"" + LIBRARY_NAME + "\">\n"
                + "        <CLASSES>\n          <root url=\"" + jarUrl(plan, "") + "\" />\n        </CLASSES>\n"
                + "        <JAVADOC>\n          <root url=\"" + jarUrl(plan, "javadoc") + "\" />\n        </JAVADOC>\n"
                + "        <SOURCES>\n          <root url=\"" + jarUrl(plan, "sources") + "\" />\n        </SOURCES>\n"
                + "      </library>\n    </orderEntry>\n  ";
        return iml.substring(0, end) + entry + iml.substring(end);
    }

    /**
     * @param compilerXml {@code .idea/compiler.xml} as it is, or null when there is none
     * @param files       the files to keep out of the IDE's compile, relative to the project
     * @return the file with each one excluded (new when there was none)
     */
    static String exclude(String compilerXml, List<String> files) {
        String xml = compilerXml != null ? compilerXml
                : "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<project version=\"4\">\n</project>\n";
        StringBuilder entries = new StringBuilder();
        for (String f : files) {
            String url = "file://$PROJECT_DIR$/" + f;
            if (!xml.contains("\"" + url + "\"")) entries.append("      <file url=\"").append(url).append("\" />\n");
        }
        if (entries.length() == 0) return xml;
        Matcher m = COMPILER_CONFIGURATION.matcher(xml);
        if (m.find()) {
            int excludes = xml.indexOf("<excludeFromCompile>", m.end());
            int close = xml.indexOf("</component>", m.end());
            if (excludes >= 0 && excludes < close) {
                int at = xml.indexOf('\n', excludes) + 1;
                return xml.substring(0, at) + entries + xml.substring(at);
            }
            return xml.substring(0, close) + "  <excludeFromCompile>\n" + entries + "    </excludeFromCompile>\n  "
                    + xml.substring(close);
        }
        int end = xml.lastIndexOf("</project>");
        return xml.substring(0, end) + "  <component name=\"CompilerConfiguration\">\n    <excludeFromCompile>\n" + entries
                + "    </excludeFromCompile>\n  </component>\n" + xml.substring(end);
    }
}
