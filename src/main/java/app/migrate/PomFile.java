package app.migrate;

import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;

import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.transform.OutputKeys;
import javax.xml.transform.TransformerException;
import javax.xml.transform.TransformerFactory;
import javax.xml.transform.dom.DOMSource;
import javax.xml.transform.stream.StreamResult;

import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.InputSource;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;

/**
 * The project's {@code pom.xml}, written for a folder that had none or updated where the student
 * has one: every element the student wrote stays (their dependencies, plugins and settings, their
 * comments and layout); what the migration needs is added, or raised where it is too old to work
 * (a Java release below what the code needs, a Surefire that finds no JUnit 5 test). One
 * implementation for both: a new pom is the update of a bare one.
 */
final class PomFile {
    private static final String NS = "http://maven.apache.org/POM/4.0.0";
    private static final String STANDARD_MAIN = "src/main/java", STANDARD_TEST = "src/test/java";

    private final Document doc;
    /** What was added or raised, for the summary ("the Java release 17 -> 21"). */
    private final List<String> changes = new ArrayList<>();

    private PomFile(Document doc) {
        this.doc = doc;
    }

    /** A pom for a project that has none, named after its folder. */
    static String create(BuildPlan plan, String folderName) throws MigrationException {
        String artifact = folderName.replaceAll("[^A-Za-z0-9_.-]", "-");
        if (artifact.isEmpty() || !Character.isLetterOrDigit(artifact.charAt(0))) artifact = "course-" + artifact;
        String bare = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<!-- Written by raytracer migrate: this course project, built where it stands, on the raytracer\n"
                + "     library (docs/migrate.md in the library's repository). mvn test runs every\n"
                + "     test; the tests left out (testExcludes below) are named in course-backup/migration-report.txt. -->\n"
                + "<project xmlns=\"http://maven.apache.org/POM/4.0.0\"\n"
                + "         xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\"\n"
                + "         xsi:schemaLocation=\"http://maven.apache.org/POM/4.0.0 https://maven.apache.org/xsd/maven-4.0.0.xsd\">\n"
                + "  <modelVersion>4.0.0</modelVersion>\n  <groupId>course</groupId>\n  <artifactId>" + artifact
                + "</artifactId>\n  <version>1.0</version>\n</project>\n";
        return update(bare, plan).text;
    }

    /** The test JVM's options a migrated pom gives Surefire: the library's vector walk may then run. */
    static final String VECTOR_MODULE = "--add-modules jdk.incubator.vector";

    /** The result of an update: the new text, and what changed in words. */
    record Updated(String text, List<String> changes) {
    }

    /**
     * @throws MigrationException when the existing pom is not well-formed XML (named with its line)
     */
    static Updated update(String pom, BuildPlan plan) throws MigrationException {
        PomFile p = new PomFile(parse(pom));
        p.apply(plan);
        return new Updated(p.serialize(pom), List.copyOf(p.changes));
    }

    private void apply(BuildPlan plan) {
        Element project = doc.getDocumentElement();
        Element properties = ensure(project, "properties");
        Element release = child(properties, "maven.compiler.release");
        if (release == null) {
            append(properties, "maven.compiler.release", Integer.toString(plan.release()));
            changes.add("Java release " + plan.release());
        } else if (parseInt(release.getTextContent()) < plan.release()) {
            changes.add("Java release " + release.getTextContent().trim() + " -> " + plan.release());
            release.setTextContent(Integer.toString(plan.release()));
        }
        if (child(properties, "project.build.sourceEncoding") == null) {
            append(properties, "project.build.sourceEncoding", plan.encoding());
            if (!plan.encoding().equals("UTF-8")) changes.add("source encoding " + plan.encoding());
        }

        Element managed = ensure(ensure(project, "dependencyManagement"), "dependencies");
        // A student's own JUnit with a version of its own keeps its version: the BOM would manage
        // the platform jars around it to another release, which need not fit.
        if (findDependency(managed, "org.junit", "junit-bom") == null && !hasVersionedJUnit(project)) {
            Element bom = dependency(managed, "org.junit", "junit-bom", plan.junit());
            append(bom, "type", "pom");
            append(bom, "scope", "import");
            changes.add("JUnit BOM " + plan.junit());
        }
        Element dependencies = ensure(project, "dependencies");
        Element library = findDependency(dependencies, plan.groupId(), plan.artifactId());
        if (library == null) {
            dependency(dependencies, plan.groupId(), plan.artifactId(), plan.version());
            changes.add("dependency " + plan.library());
        } else if (child(library, "version") == null || !text(library, "version").equals(plan.version())) {
            set(library, "version", plan.version());
            changes.add("dependency " + plan.library() + " (version updated)");
        }
        if (!hasGroup(dependencies, "org.junit.jupiter")) {
            append(dependency(dependencies, "org.junit.jupiter", "junit-jupiter", null), "scope", "test");
            changes.add("dependency junit-jupiter (test)");
        }
        if (plan.junit4() && findDependency(dependencies, "org.junit.vintage", "junit-vintage-engine") == null) {
            // JUnit 4's tests run on the JUnit Platform through the Vintage engine, in the same mvn test.
            boolean bom = findDependency(managed, "org.junit", "junit-bom") != null;
            append(dependency(dependencies, "org.junit.vintage", "junit-vintage-engine", bom ? null : plan.junit()), "scope", "test");
            changes.add("dependency junit-vintage-engine (test: your JUnit 4 tests)");
        }
        for (Libraries.Library l : plan.libraries()) {
            if (findDependency(dependencies, l.group(), l.artifact()) != null) continue;
            Element d = dependency(dependencies, l.group(), l.artifact(), l.version());
            if (l.systemPath() != null) {
                append(d, "scope", "system");
                append(d, "systemPath", "${project.basedir}/" + l.systemPath());
            } else if (l.testOnly()) {
                append(d, "scope", "test");
            }
            changes.add("dependency " + l.describe());
        }

        Element build = ensure(project, "build");
        if (!plan.mainRoots().isEmpty() && !plan.mainRoots().get(0).equals(STANDARD_MAIN))
            set(build, "sourceDirectory", plan.mainRoots().get(0));
        if (!plan.testRoots().isEmpty() && !plan.testRoots().get(0).equals(STANDARD_TEST))
            set(build, "testSourceDirectory", plan.testRoots().get(0));
        Element plugins = ensure(build, "plugins");

        Element compiler = plugin(plugins, "org.apache.maven.plugins", "maven-compiler-plugin", BuildPlan.COMPILER_VERSION, "3.6");
        Element compilerConfig = ensure(compiler, "configuration");
        list(compilerConfig, "excludes", "exclude", plan.mainExcludes());
        list(compilerConfig, "testIncludes", "testInclude", plan.testIncludes());
        list(compilerConfig, "testExcludes", "testExclude", plan.testExcludes());

        Element surefire = plugin(plugins, "org.apache.maven.plugins", "maven-surefire-plugin", BuildPlan.SUREFIRE_VERSION, "3.0");
        // Every test class, whatever its name: Surefire's default runs only *Test, Test*, *Tests
        // and *TestCase, and the course's CameraIntersectionIntegration is none of them.
        Element surefireConfig = ensure(surefire, "configuration");
        list(surefireConfig, "includes", "include", List.of("**/*.java"));
        // The test JVM reads the vector module, as the README's pom gives it: a long render then
        // takes the vector walk (docs/student-guide.md). A JVM option the project sets already,
        // as a property or in Surefire's configuration, is left as it is.
        if (child(properties, "argLine") == null && child(surefireConfig, "argLine") == null)
            append(properties, "argLine", VECTOR_MODULE);

        List<String> extraMain = plan.mainRoots().size() > 1 ? plan.mainRoots().subList(1, plan.mainRoots().size()) : List.of();
        List<String> extraTest = plan.testRoots().size() > 1 ? plan.testRoots().subList(1, plan.testRoots().size()) : List.of();
        if (!extraMain.isEmpty() || !extraTest.isEmpty()) {
            Element helper = plugin(plugins, "org.codehaus.mojo", "build-helper-maven-plugin", BuildPlan.BUILD_HELPER_VERSION, "0");
            Element executions = ensure(helper, "executions");
            if (!extraMain.isEmpty()) helperExecution(executions, "add-course-sources", "add-source", "sources", "source", extraMain);
            if (!extraTest.isEmpty())
                helperExecution(executions, "add-course-tests", "add-test-source", "sources", "source", extraTest);
        }
    }

    private void helperExecution(Element executions, String id, String goal, String listName, String itemName, List<String> items) {
        for (Element e : children(executions, "execution"))
            if (id.equals(text(e, "id"))) return;
        Element execution = append(executions, "execution", null);
        append(execution, "id", id);
        append(execution, "phase", goal.equals("add-source") ? "generate-sources" : "generate-test-sources");
        append(ensure(execution, "goals"), "goal", goal);
        list(ensure(execution, "configuration"), listName, itemName, items);
        changes.add("extra folders " + String.join(", ", items));
    }

    /** The plugin, added when missing, its version set when missing or older than {@code minimum}. */
    private Element plugin(Element plugins, String group, String artifact, String version, String minimum) {
        for (Element p : children(plugins, "plugin")) {
            if (!artifact.equals(text(p, "artifactId"))) continue;
            String v = text(p, "version");
            if (v.isEmpty() || (!v.startsWith("${") && compareVersions(v, minimum) < 0)) {
                set(p, "version", version);
                changes.add(artifact + " " + (v.isEmpty() ? "" : v + " -> ") + version);
            }
            return p;
        }
        Element p = append(plugins, "plugin", null);
        append(p, "groupId", group);
        append(p, "artifactId", artifact);
        append(p, "version", version);
        changes.add(artifact + " " + version);
        return p;
    }

    /** {@code <excludes><exclude>a</exclude>…</excludes>}, adding the items not there yet. */
    private void list(Element parent, String listName, String itemName, List<String> items) {
        if (items.isEmpty()) return;
        Element list = ensure(parent, listName);
        List<String> present = children(list, itemName).stream().map(e -> e.getTextContent().trim()).toList();
        for (String item : items)
            if (!present.contains(item)) append(list, itemName, item);
    }

    private Element dependency(Element dependencies, String group, String artifact, String version) {
        Element d = append(dependencies, "dependency", null);
        append(d, "groupId", group);
        append(d, "artifactId", artifact);
        if (version != null) append(d, "version", version);
        return d;
    }

    private Element findDependency(Element dependencies, String group, String artifact) {
        for (Element d : children(dependencies, "dependency"))
            if (group.equals(text(d, "groupId")) && artifact.equals(text(d, "artifactId"))) return d;
        return null;
    }

    private static boolean hasVersionedJUnit(Element project) {
        Element dependencies = child(project, "dependencies");
        return dependencies != null && children(dependencies, "dependency").stream()
                .anyMatch(d -> text(d, "groupId").startsWith("org.junit") && child(d, "version") != null);
    }

    private boolean hasGroup(Element dependencies, String group) {
        return children(dependencies, "dependency").stream().anyMatch(d -> group.equals(text(d, "groupId")));
    }

    // ===== DOM helpers that keep the file's two-space layout =====

    private static List<Element> children(Element parent, String name) {
        List<Element> found = new ArrayList<>();
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling())
            if (n instanceof Element e && name.equals(e.getLocalName() != null ? e.getLocalName() : e.getTagName()))
                found.add(e);
        return found;
    }

    private static Element child(Element parent, String name) {
        List<Element> found = children(parent, name);
        return found.isEmpty() ? null : found.get(0);
    }

    private static String text(Element parent, String name) {
        Element e = child(parent, name);
        return e == null ? "" : e.getTextContent().trim();
    }

    private Element ensure(Element parent, String name) {
        Element e = child(parent, name);
        return e != null ? e : append(parent, name, null);
    }

    private void set(Element parent, String name, String value) {
        Element e = child(parent, name);
        if (e == null) append(parent, name, value);
        else e.setTextContent(value);
    }

    /** Appends a child on its own line, indented one level below its parent. */
    private Element append(Element parent, String name, String value) {
        int depth = 0;
        for (Node n = parent; n.getParentNode() != null && n.getParentNode().getNodeType() == Node.ELEMENT_NODE; n = n.getParentNode())
            depth++;
        String ns = doc.getDocumentElement().getNamespaceURI();
        Element e = ns == null ? doc.createElement(name) : doc.createElementNS(ns, name);
        if (value != null) e.setTextContent(value);
        Node last = parent.getLastChild();
        boolean closingIndent = last != null && last.getNodeType() == Node.TEXT_NODE && last.getTextContent().isBlank();
        Node anchor = closingIndent ? last : null;
        parent.insertBefore(doc.createTextNode("\n" + "  ".repeat(depth + 1)), anchor);
        parent.insertBefore(e, anchor);
        if (!closingIndent) parent.appendChild(doc.createTextNode("\n" + "  ".repeat(depth)));
        return e;
    }

    /**
     * Checks that a pom can be read and updated, before the migration compiles anything.
     *
     * @throws MigrationException naming the line and column of what is not well-formed, or the root that is not {@code <project>}
     */
    static void check(String pom) throws MigrationException {
        parse(pom);
    }

    private static Document parse(String pom) throws MigrationException {
        try {
            DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
            f.setNamespaceAware(true);
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setAttribute(XMLConstants.ACCESS_EXTERNAL_DTD, "");
            f.setAttribute(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
            var builder = f.newDocumentBuilder();
            // the parser's default handler prints "[Fatal Error] …" itself: the refusal below says it once
            builder.setErrorHandler(new org.xml.sax.helpers.DefaultHandler() {
                @Override
                public void fatalError(SAXParseException e) throws SAXException {
                    throw e;
                }
            });
            Document d = builder.parse(new InputSource(new StringReader(pom)));
            if (!"project".equals(d.getDocumentElement().getLocalName()))
                throw new MigrationException("pom.xml is not a Maven pom (its root element is <"
                        + d.getDocumentElement().getTagName() + ">)");
            return d;
        } catch (SAXParseException e) {
            throw new MigrationException("pom.xml is not well-formed XML (line " + e.getLineNumber() + ", column " + e.getColumnNumber()
                    + ": " + e.getMessage() + "): fix it first (nothing was changed)");
        } catch (SAXException e) {
            throw new MigrationException("pom.xml is not well-formed XML: " + e.getMessage() + "; fix it first (nothing was changed)");
        } catch (ParserConfigurationException | IOException e) {
            throw new MigrationException("cannot read pom.xml: " + e.getMessage(), e);
        }
    }

    private String serialize(String original) throws MigrationException {
        try {
            var t = TransformerFactory.newInstance().newTransformer();
            t.setOutputProperty(OutputKeys.OMIT_XML_DECLARATION, "yes");
            StringWriter w = new StringWriter();
            t.transform(new DOMSource(doc), new StreamResult(w));
            // The declaration as the student wrote it (the transformer's own has no newline after it).
            String declaration = original.startsWith("<?xml") ? original.substring(0, original.indexOf("?>") + 2) + "\n" : "";
            String body = w.toString().replaceFirst("-->(?=<project)", "-->\n");
            return declaration + body + (body.endsWith("\n") ? "" : "\n");
        } catch (TransformerException e) {
            throw new MigrationException("cannot write pom.xml: " + e.getMessage(), e);
        }
    }

    private static int parseInt(String s) {
        String t = s.trim().replaceFirst("^1\\.", "");
        try {
            return Integer.parseInt(t);
        } catch (NumberFormatException e) {
            return 0; // ${java.version} and the like: raised to what the code needs
        }
    }

    /** Compares dotted versions numerically ({@code 2.12.4} < {@code 3.0}); a qualifier counts as 0. */
    static int compareVersions(String a, String b) {
        String[] x = a.split("[.-]"), y = b.split("[.-]");
        for (int i = 0; i < Math.max(x.length, y.length); i++) {
            int p = i < x.length ? leading(x[i]) : 0, q = i < y.length ? leading(y[i]) : 0;
            if (p != q) return Integer.compare(p, q);
        }
        return 0;
    }

    private static int leading(String s) {
        int n = 0, i = 0;
        while (i < s.length() && Character.isDigit(s.charAt(i)) && n < 100_000) n = n * 10 + (s.charAt(i++) - '0');
        return n;
    }
}
