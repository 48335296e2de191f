package app.migrate;

import com.sun.source.tree.MethodTree;

/**
 * A method of a test file that may be taken out, and the text its removal replaces: {@code [start,
 * end)}, its Javadoc and comment lines above and the line break after it included.
 *
 * @param treeStart where javac puts the method (its annotations included): file order
 * @param indent    the blanks its comment line starts with ({@code ""} when code precedes it on its line)
 * @param lineBreak what ends its comment line
 * @param test      whether JUnit runs it ({@code @Test} and its kin)
 * @param removable whether taking it out leaves the remaining tests as they were (no constructor,
 *                  lifecycle method or override)
 */
record MethodSpan(MethodTree tree, String name, long treeStart, int start, int end, String indent, String lineBreak,
        boolean test, boolean removable) {
}
