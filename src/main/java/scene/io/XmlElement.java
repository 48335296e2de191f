package scene.io;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;

/**
 * One element of a scene file: its name, attributes and child elements, and where it stands in
 * the file, so that every complaint about it can name the line and column. Attribute values are
 * read through {@link ValueType}s, which parse strictly and independently of the locale.
 */
final class XmlElement {
    private final String name;
    private final Map<String, String> attributes;
    private final List<XmlElement> children = new ArrayList<>();
    private final SourceText source;
    private final String file;
    /** Offset of the start tag's '<' in the source text. */
    private final int start;
    /** Attribute name → offset of the name in the start tag; computed on the first error. */
    private Map<String, Integer> attributeOffsets;

    XmlElement(String name, Map<String, String> attributes, SourceText source, String file, int start) {
        this.name = name;
        this.attributes = Collections.unmodifiableMap(new LinkedHashMap<>(attributes));
        this.source = source;
        this.file = file;
        this.start = start;
    }

    String name() {
        return name;
    }

    List<XmlElement> children() {
        return Collections.unmodifiableList(children);
    }

    void addChild(XmlElement child) {
        children.add(child);
    }

    int line() {
        return source.line(start);
    }

    int column() {
        return source.column(start);
    }

    boolean has(String attribute) {
        return attributes.containsKey(attribute);
    }

    /** The attribute names, in document order. */
    Set<String> attributeNames() {
        return attributes.keySet();
    }

    /**
     * Rejects every attribute not in {@code allowed}, naming the first unknown one and the
     * allowed ones.
     */
    void allowAttributes(List<String> allowed) throws SceneFormatException {
        for (String attribute : attributes.keySet())
            if (!allowed.contains(attribute))
                throw errorAt(attribute, "unknown attribute '" + attribute + "' on <" + name + "> (expected "
                        + (allowed.isEmpty() ? "no attributes" : "one of: " + String.join(", ", allowed)) + ")");
    }

    /** @return the value of a required attribute */
    <T> T required(String attribute, ValueType<T> type) throws SceneFormatException {
        if (!has(attribute))
            throw error("<" + name + "> is missing attribute '" + attribute + "' (expected " + type.expected() + ")");
        return optional(attribute, type, null);
    }

    /** @return the value of an optional attribute, or {@code otherwise} when it is absent */
    <T> T optional(String attribute, ValueType<T> type, T otherwise) throws SceneFormatException {
        String text = attributes.get(attribute);
        if (text == null) return otherwise;
        try {
            return type.parse(text);
        } catch (IllegalArgumentException e) {
            throw errorAt(attribute, quote(attribute) + ": " + e.getMessage() + " (expected " + type.expected() + ")", e);
        }
    }

    /**
     * Hands an optional attribute's value to a setter of the library; a value the setter refuses
     * is reported at the attribute with the setter's message.
     */
    <T> void ifPresent(String attribute, ValueType<T> type, Consumer<T> setter) throws SceneFormatException {
        T value = optional(attribute, type, null);
        if (value == null) return;
        try {
            setter.accept(value);
        } catch (IllegalArgumentException e) {
            throw errorAt(attribute, quote(attribute) + ": " + e.getMessage() + " (expected " + type.expected() + ")", e);
        }
    }

    /** {@code <name attribute="value">}, for messages. */
    String quote(String attribute) {
        return "<" + name + " " + attribute + "=\"" + visible(attributes.get(attribute)) + "\">";
    }

    /** {@code value} as {@link Messages#visible(String)} writes it: one line, nothing hidden. */
    private static String visible(String value) {
        return Messages.visible(value);
    }

    /** An error at the start of this element's tag. */
    SceneFormatException error(String reason) {
        return new SceneFormatException(file, line(), column(), reason);
    }

    /** An error at the start of this element's tag, caused by {@code cause}. */
    SceneFormatException error(String reason, Throwable cause) {
        return new SceneFormatException(file, line(), column(), reason, cause);
    }

    /** An error at the attribute's name in the start tag (at the tag when it cannot be found). */
    SceneFormatException errorAt(String attribute, String reason) {
        return errorAt(attribute, reason, null);
    }

    /** An error at the attribute, caused by {@code cause}. */
    SceneFormatException errorAt(String attribute, String reason, Throwable cause) {
        Integer offset = attributeOffsets().get(attribute);
        if (offset == null) return error(reason, cause);
        return new SceneFormatException(file, source.line(offset), source.column(offset), reason, cause);
    }

    /**
     * Finds each attribute's name in the start tag. The parser has already checked the tag, so a
     * simple scan suffices: '<' and the quotes cannot occur unescaped inside attribute values.
     */
    private Map<String, Integer> attributeOffsets() {
        if (attributeOffsets != null) return attributeOffsets;
        Map<String, Integer> offsets = new HashMap<>();
        String text = source.text();
        int i = start + 1;
        while (i < text.length() && !isNameEnd(text.charAt(i))) ++i;
        while (i < text.length()) {
            while (i < text.length() && Character.isWhitespace(text.charAt(i))) ++i;
            if (i >= text.length() || text.charAt(i) == '/' || text.charAt(i) == '>') break;
            int nameStart = i;
            while (i < text.length() && text.charAt(i) != '=' && !Character.isWhitespace(text.charAt(i))) ++i;
            String attribute = text.substring(nameStart, i);
            while (i < text.length() && text.charAt(i) != '"' && text.charAt(i) != '\'') ++i;
            if (i >= text.length()) break;
            int close = text.indexOf(text.charAt(i), i + 1);
            if (close < 0) break;
            offsets.put(attribute, nameStart);
            i = close + 1;
        }
        attributeOffsets = offsets;
        return offsets;
    }

    private static boolean isNameEnd(char c) {
        return Character.isWhitespace(c) || c == '/' || c == '>';
    }
}
