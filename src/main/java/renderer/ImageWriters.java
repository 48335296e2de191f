package renderer;

/**
 * What the scene reader, the command line, the JUnit helpers and the Spark entry ask of images
 * beside the course's {@link ImageWriter}: the memory an image needs, the rule of an image name
 * that untrusted input chooses, and the copy of a tile rendered elsewhere. Static, and apart from
 * {@link ImageWriter}, so that a student completing {@code imageWriter.} or {@code ImageWriter.}
 * sees the course's methods only.
 *
 * @hidden internal: the engine's questions about images; a scene test writes pixels and the image
 */
public final class ImageWriters {
    /**
     * The longest image name {@link #requireFileName} allows, in characters (file names have at
     * most 255 bytes).
     */
    public static final int MAX_FILE_NAME_LENGTH = ImageWriter.MAX_FILE_NAME_LENGTH;

    private ImageWriters() {
    }

    /**
     * What an image of nX × nY pixels needs, against what this JVM may use, for a one-line
     * message: {@code image 40000x40000 needs 6104 MB; Java may use at most 2048 MB here}; when
     * the image is within that limit (refused all the same, as the rest of the program holds
     * memory too), the sentence adds what was free.
     *
     * @param nX the number of columns
     * @param nY the number of rows
     * @return the sentence, without advice (the caller knows how its user makes an image smaller)
     */
    public static String memoryNeeded(int nX, int nY) {
        return ImageWriter.memoryNeeded(nX, nY);
    }

    /**
     * @param nX the number of columns
     * @param nY the number of rows
     * @return the bytes of the pixels of an nX × nY image: 4 a pixel
     */
    public static long bytesNeeded(int nX, int nY) {
        return ImageWriter.bytesNeeded(nX, nY);
    }

    /**
     * Checks that {@code name} names a file in images/ and nothing else: the rule of an image name
     * that untrusted input (a scene file) chooses, which must not choose where on disk its image
     * goes. (The course's own constructor and {@link ImageWriter#writeToImage(String)} take
     * sub-folders.)
     *
     * @param name the image name, without ".png"
     * @return {@code name}
     * @throws NullPointerException     for a null name
     * @throws IllegalArgumentException for a blank name, one longer than
     *                                  {@link #MAX_FILE_NAME_LENGTH}, or one with a path separator
     *                                  ({@code /} or {@code \}), a drive colon or {@code ..},
     *                                  naming it; for one with a character that would not show
     *                                  as what it is ({@link #hiddenCharacter}), naming its code
     *                                  point and its kind
     */
    public static String requireFileName(String name) {
        return ImageWriter.requireFileName(name);
    }

    /**
     * Why code point {@code cp} may not stand in a name, or null when it may: control, format,
     * separator and non-ASCII space characters, private-use, unassigned and surrogate code points,
     * the rest of Unicode's Default_Ignorable_Code_Point and the blank braille pattern U+2800.
     *
     * @param cp a Unicode code point
     * @return the kind of character, for a message ("a control character", …), or null
     */
    public static String hiddenCharacter(int cp) {
        return ImageWriter.hiddenCharacter(cp);
    }

    /**
     * Copies a rectangle of packed 0xRRGGBB pixels (as {@link ImageWriter#getRgb} gives them) into
     * the image: a tile rendered elsewhere (a Spark executor, a comparison's difference image).
     *
     * @param image  the image written
     * @param x      the rectangle's first column
     * @param y      the rectangle's first row
     * @param width  its number of columns, positive
     * @param height its number of rows, positive
     * @param rgb    its pixels, row after row, {@code width} to a row; may be longer
     * @throws IndexOutOfBoundsException naming the rectangle when it does not lie in the image or
     *                                   {@code rgb} is too short for it; nothing is written then
     */
    public static void writeTile(ImageWriter image, int x, int y, int width, int height, int[] rgb) {
        image.writeTile(x, y, width, height, rgb);
    }
}
