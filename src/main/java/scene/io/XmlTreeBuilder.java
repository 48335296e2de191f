package scene.io;

import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParserFactory;

import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXNotRecognizedException;
import org.xml.sax.SAXNotSupportedException;
import org.xml.sax.SAXParseException;
import org.xml.sax.XMLReader;
import org.xml.sax.helpers.DefaultHandler;

/**
 * Parses scene-file text with the JDK's SAX parser into {@link XmlElement}s that know their
 * position. Hardened against hostile files: DOCTYPE declarations (and with them every external
 * entity, external DTD and entity-expansion bomb) are refused, XInclude is off, the JDK's
 * secure-processing limits apply, and elements nest at most {@link Limits#MAX_NESTING_DEPTH} deep. Parser messages are requested in the base (English) language so
 * that the one-line error does not depend on the machine's locale.
 */
final class XmlTreeBuilder extends DefaultHandler {
    private static final String DISALLOW_DOCTYPE = "http://apache.org/xml/features/disallow-doctype-decl";
    private static final String PARSER_LOCALE = "http://apache.org/xml/properties/locale";

    private final SourceText source;
    private final String file;
    private final Deque<XmlElement> open = new ArrayDeque<>();
    private Locator locator;
    private XmlElement root;
    /** Offset just after the last tag the parser reported: where following text begins. */
    private int lastTagEnd;

    private XmlTreeBuilder(SourceText source, String file) {
        this.source = source;
        this.file = file;
    }

    /**
     * @param text the file's text (already decoded; a byte-order mark removed)
     * @param file the file's name as the user gave it, for messages
     * @return the root element
     */
    static XmlElement parse(String text, String file) throws SceneFormatException {
        SourceText source = new SourceText(text);
        XmlTreeBuilder builder = new XmlTreeBuilder(source, file);
        try {
            XMLReader reader = newReader();
            reader.setContentHandler(builder);
            reader.setErrorHandler(builder);
            InputSource input = new InputSource(new StringReader(text));
            input.setSystemId(file);
            reader.parse(input);
        } catch (SAXParseException e) {
            rethrowOwn(e);
            throw new SceneFormatException(file, Math.max(e.getLineNumber(), 0), Math.max(e.getColumnNumber(), 0),
                    describe(e));
        } catch (SAXException e) {
            rethrowOwn(e);
            throw new SceneFormatException(file, 0, 0, "malformed XML: " + e.getMessage() + " (expected a well-formed XML scene file)");
        } catch (IOException e) {
            // Reading from a string cannot fail; an entity resolution would, but DOCTYPEs are refused.
            throw new SceneFormatException(file, 0, 0, "cannot read: " + e.getMessage() + " (expected a readable file)", e);
        }
        if (builder.root == null)
            throw new SceneFormatException(file, 1, 1, "the file has no root element (expected <scene>)");
        return builder.root;
    }

    /** Our own complaints travel through the parser wrapped in a SAXException. */
    private static void rethrowOwn(SAXException e) throws SceneFormatException {
        for (Throwable t = e; t != null; t = t.getCause())
            if (t instanceof SceneFormatException sfe) throw sfe;
    }

    private static String describe(SAXParseException e) {
        String message = String.valueOf(e.getMessage()).strip();
        if (message.contains(DISALLOW_DOCTYPE))
            return "a DOCTYPE declaration (expected a scene file without DTD or entities: they are refused for safety)";
        if (message.endsWith(".")) message = message.substring(0, message.length() - 1);
        return "malformed XML: " + message + " (expected a well-formed XML scene file)";
    }

    private static XMLReader newReader() throws SAXException {
        try {
            // The JDK's own parser, whose features these are (newInstance() would take whichever a
            // jar on the class path declares, after a service lookup of about 6 ms a launch).
            SAXParserFactory factory = SAXParserFactory.newDefaultInstance();
            factory.setNamespaceAware(false);
            factory.setValidating(false);
            factory.setXIncludeAware(false);
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            XMLReader reader = factory.newSAXParser().getXMLReader();
            // On the reader, not the factory: the factory builds a whole parser to try each other
            // feature it is given (4 ms of a launch for these four).
            reader.setFeature(DISALLOW_DOCTYPE, true);
            reader.setFeature("http://xml.org/sax/features/external-general-entities", false);
            reader.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
            reader.setFeature("http://apache.org/xml/features/nonvalidating/load-external-dtd", false);
            // ROOT, not ENGLISH: there is no English bundle, so ENGLISH would fall back to the
            // default locale's (German on a German machine); ROOT selects the base bundle.
            reader.setProperty(PARSER_LOCALE, Locale.ROOT);
            return reader;
        } catch (ParserConfigurationException | SAXNotRecognizedException | SAXNotSupportedException e) {
            throw new IllegalStateException("the JDK's SAX parser does not support the secure configuration: " + e.getMessage(), e);
        }
    }

    @Override
    public void setDocumentLocator(Locator locator) {
        this.locator = locator;
    }

    /** The offset of the parser's current position: just after the tag it reports. */
    private int here() {
        return source.offset(locator.getLineNumber(), locator.getColumnNumber());
    }

    @Override
    public void startElement(String uri, String localName, String qName, Attributes attributes) throws SAXException {
        int end = here();
        // The parser reports the end of the start tag; its '<' is the last one before (attribute
        // values cannot contain an unescaped '<').
        int start = source.text().lastIndexOf('<', Math.max(0, end - 1));
        if (start < 0) start = Math.max(0, end - 1);
        Map<String, String> map = new LinkedHashMap<>();
        for (int i = 0; i < attributes.getLength(); ++i) map.put(attributes.getQName(i), attributes.getValue(i));
        XmlElement element = new XmlElement(qName, map, source, file, start);
        if (open.size() >= Limits.MAX_NESTING_DEPTH)
            throw new SAXException(element.error("<" + qName + "> is nested " + (open.size() + 1)
                    + " elements deep (expected at most " + Limits.MAX_NESTING_DEPTH + ", the limit)"));
        if (open.isEmpty()) root = element;
        else open.peek().addChild(element);
        open.push(element);
        lastTagEnd = end;
    }

    @Override
    public void endElement(String uri, String localName, String qName) {
        open.pop();
        lastTagEnd = here();
    }

    /** Scene files hold no text: a non-blank run of characters is a mistake worth reporting. */
    @Override
    public void characters(char[] ch, int start, int length) throws SAXException {
        for (int i = start; i < start + length; ++i)
            if (!Character.isWhitespace(ch[i])) {
                String text = new String(ch, start, length).strip();
                if (text.length() > 30) text = text.substring(0, 27) + "...";
                int offset = lastTagEnd;
                String all = source.text();
                while (offset < all.length() && Character.isWhitespace(all.charAt(offset))) ++offset;
                String where = open.isEmpty() ? "outside the root element" : "in <" + open.peek().name() + ">";
                SceneFormatException e = new SceneFormatException(file, source.line(offset), source.column(offset),
                        "unexpected text \"" + text + "\" " + where + " (expected only elements; values go in attributes)");
                throw new SAXException(e);
            }
    }

    // Report every problem as fatal, and never print to System.err as the default handler does.
    @Override
    public void warning(SAXParseException e) {
        // Warnings (none are expected without DTDs) do not make a file invalid.
    }

    @Override
    public void error(SAXParseException e) throws SAXException {
        throw e;
    }

    @Override
    public void fatalError(SAXParseException e) throws SAXException {
        throw e;
    }
}
