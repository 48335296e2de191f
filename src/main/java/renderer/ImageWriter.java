package renderer;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;
import java.util.Objects;

import javax.imageio.ImageIO;


import primitives.Color;
import primitives.CourseClassGuard;

/**
 * A pixel buffer of {@code nX × nY} pixels written as a PNG. {@code x} is the column (0 at the
 * left) and {@code y} the row (0 at the top). Different threads may write different pixels; the
 * render loop publishes them before {@link #writeToImage()} is called.
 */
public class ImageWriter {
    /** Where images go, relative to the working directory (the project root in tests). */
    public static final Path IMAGES = Path.of("images");
    /**
     * The most pixels an image can have: they are kept in one {@code int} array, and JVMs allocate
     * arrays of at most {@code Integer.MAX_VALUE - 8} elements.
     */
    public static final long MAX_PIXELS = Integer.MAX_VALUE - 8;
    /**
     * The longest image name {@link #requireFileName} allows, in characters (file names have at
     * most 255 bytes).
     */
    static final int MAX_FILE_NAME_LENGTH = 200;

    private final String imageName;
    private final int nX;
    private final int nY;
    /** Packed 0xRRGGBB per pixel, row-major. */
    private final int[] pixels;
    /**
     * Whether any pixel was written: a write of an image nothing was drawn on (a render or grid
     * forgotten) says so rather than leave an all-black PNG unexplained. Set by every pixel write,
     * by any thread; read after the render, whose end orders the workers' writes before it.
     */
    private boolean drawn;

    /**
     * @param imageName the file name without ".png"; may contain sub-folders ("golden/spheres")
     * @param nX        the number of columns, positive
     * @param nY        the number of rows, positive
     * @throws IllegalArgumentException for a blank name or a non-positive size
     * @throws OutOfMemoryError         when the pixels do not fit the heap, naming the size, the
     *                                  memory it needs and the most this JVM may use
     */
    public ImageWriter(String imageName, int nX, int nY) {
        this(nX, nY, checkName(imageName));
    }

    /**
     * A writer without a name yet (the 2024–25 course's form): give the name when writing, with
     * {@link #writeToImage(String)}.
     *
     * @param nX the number of columns, positive
     * @param nY the number of rows, positive
     * @throws IllegalArgumentException for a non-positive size
     * @throws OutOfMemoryError         when the pixels do not fit the heap, naming the size, the
     *                                  memory it needs and the most this JVM may use
     */
    public ImageWriter(int nX, int nY) {
        this(nX, nY, null);
    }

    private ImageWriter(int nX, int nY, String imageName) {
        CourseClassGuard.check();
        if (nX <= 0 || nY <= 0)
            throw new IllegalArgumentException("image size must be positive, got " + nX + "x" + nY);
        if ((long) nX * nY > MAX_PIXELS)
            throw new IllegalArgumentException("image size " + nX + "x" + nY + " has too many pixels");
        this.imageName = imageName;
        this.nX = nX;
        this.nY = nY;
        this.pixels = allocate(nX, nY);
    }

    /**
     * The pixel buffer, the one allocation that grows with the image. A lack of memory is caught
     * at this very allocation, not guessed before it from the heap's free space (which the
     * collector may still grow, or which may be too fragmented for one array): the error then
     * names what was asked.
     */
    private static int[] allocate(int nX, int nY) {
        try {
            return new int[nX * nY];
        } catch (OutOfMemoryError e) {
            OutOfMemoryError named = new OutOfMemoryError(memoryNeeded(nX, nY)
                    + " (render it smaller, or give Java more memory with -Xmx)");
            named.initCause(e);
            throw named;
        }
    }

    /**
     * What an image of nX × nY pixels needs, against what this JVM may use, for a one-line
     * message: {@code image 40000x40000 needs 6104 MB; Java may use at most 2048 MB here}; when
     * the image is within that limit (refused all the same, as the rest of the program holds
     * memory too), the sentence adds what was free: {@code image 23160x23160 needs 2047 MB; Java
     * may use at most 2048 MB here, of which about 1900 MB were free for it (the image is one array)}.
     *
     * @param nX the number of columns
     * @param nY the number of rows
     * @return the sentence, without advice (the caller knows how its user makes an image smaller)
     */
    static String memoryNeeded(int nX, int nY) {
        long mb = 1 << 20;
        Runtime runtime = Runtime.getRuntime();
        long max = runtime.maxMemory();
        long needed = bytesNeeded(nX, nY);
        String sentence = "image " + nX + "x" + nY + " needs " + (needed + mb - 1) / mb + " MB";
        if (max == Long.MAX_VALUE) return sentence;
        sentence += "; Java may use at most " + (max >> 20) + " MB here";
        // Within the limit yet refused: what the rest of the program holds is the difference, so
        // say how much was left (an estimate: the collector may still free some).
        long used = runtime.totalMemory() - runtime.freeMemory();
        return needed <= max ? sentence + ", of which about " + Math.max(0, max - used) / mb
                + " MB were free for it (the image is one array)" : sentence;
    }

    /**
     * @param nX the number of columns
     * @param nY the number of rows
     * @return the bytes of the pixels of an nX × nY image: 4 a pixel
     */
    static long bytesNeeded(int nX, int nY) {
        return (long) nX * nY * Integer.BYTES;
    }

    private static String checkName(String imageName) {
        Objects.requireNonNull(imageName, "image name");
        if (imageName.isBlank()) throw new IllegalArgumentException("image name must not be blank");
        return imageName;
    }

    /**
     * Checks that {@code name} names a file in images/ and nothing else: the rule of an image name
     * that untrusted input (a scene file) chooses, which must not choose where on disk its image
     * goes. (The course's own constructor and {@link #writeToImage(String)} take sub-folders.)
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
    static String requireFileName(String name) {
        Objects.requireNonNull(name, "image name");
        if (name.isBlank()) throw new IllegalArgumentException("the image name is blank");
        if (name.length() > MAX_FILE_NAME_LENGTH)
            throw new IllegalArgumentException("the image name has " + name.length() + " characters, more than the limit of "
                    + MAX_FILE_NAME_LENGTH);
        name.codePoints().filter(cp -> hiddenCharacter(cp) != null).findFirst().ifPresent(cp -> {
            throw new IllegalArgumentException(String.format(Locale.ROOT, "the image name contains U+%04X, %s (the file"
                    + " name would display as something else, or not at all)", cp, hiddenCharacter(cp)));
        });
        for (int i = 0; i < name.length(); ++i) {
            char c = name.charAt(i);
            if (c == '/' || c == '\\' || c == ':')
                throw new IllegalArgumentException("the image name '" + name + "' is a path, not a name (it contains '" + c + "')");
        }
        if (name.contains(".."))
            throw new IllegalArgumentException("the image name '" + name + "' contains '..' (a name, not a path, is expected)");
        return name;
    }

    /**
     * Why code point {@code cp} may not stand in a name, or null when it may. The rule, in the
     * order asked: control characters (Unicode Cc: C0, DEL and C1, such as U+009B, which a
     * terminal obeys); format characters (Cf: the bidirectional overrides and isolates, the
     * direction marks, zero-width characters); line and paragraph separators (Zl, Zp); spaces
     * other than U+0020 (Zs: U+00A0, U+3000, …: they look like the plain space and are another
     * character); private-use, unassigned and surrogate code points (Co, Cn, Cs: no agreed glyph);
     * the rest of Unicode's Default_Ignorable_Code_Point (U+034F, the Hangul fillers U+115F,
     * U+1160, U+3164 and U+FFA0, the variation selectors U+FE00–U+FE0F, …: drawn as nothing);
     * and the blank-looking symbols ({@link #blankLooking}: U+2800, U+1D159, U+16FE4), drawn as a space.
     *
     * @param cp a Unicode code point
     * @return the kind of character, for a message ("a control character", …), or null
     */
    static String hiddenCharacter(int cp) {
        return switch (Character.getType(cp)) {
            case Character.CONTROL -> "a control character";
            case Character.FORMAT -> "an invisible or direction-changing character";
            case Character.LINE_SEPARATOR, Character.PARAGRAPH_SEPARATOR -> "a line or paragraph separator";
            case Character.SPACE_SEPARATOR -> cp == ' ' ? null : "a space other than U+0020 (it looks like one and is another character)";
            case Character.PRIVATE_USE, Character.UNASSIGNED, Character.SURROGATE -> "a private-use, unassigned or surrogate code point";
            default -> defaultIgnorable(cp) ? "an invisible character (Unicode's Default_Ignorable_Code_Point)" : blankLooking(cp);
        };
    }

    /**
     * The blank-looking rule: characters of a visible category (a symbol, a letter) that fonts draw
     * as an empty box-less space, so that a name holding one looks like another name: the empty
     * braille pattern U+2800 (So), the musical symbol null notehead U+1D159 (So) and the Khitan
     * small script filler U+16FE4 (a mark that stands alone). Unicode names them nowhere as a class;
     * they are the ones lists of "invisible characters" give that no category above catches.
     *
     * @return the character's description for the message, or null for any other
     */
    private static String blankLooking(int cp) {
        return switch (cp) {
            case 0x2800 -> "a blank-looking character (the empty braille pattern)";
            case 0x1D159 -> "a blank-looking character (the musical null notehead)";
            case 0x16FE4 -> "a blank-looking character (the Khitan small script filler)";
            default -> null;
        };
    }

    /**
     * Unicode's Default_Ignorable_Code_Point (DerivedCoreProperties, Unicode 15) outside the
     * format category, which {@link #hiddenCharacter} names first: characters drawn as nothing.
     */
    private static boolean defaultIgnorable(int cp) {
        return cp == 0x034F || cp == 0x115F || cp == 0x1160 || cp == 0x17B4 || cp == 0x17B5
                || (cp >= 0x180B && cp <= 0x180F) || (cp >= 0x2060 && cp <= 0x206F) || cp == 0x3164
                || (cp >= 0xFE00 && cp <= 0xFE0F) || cp == 0xFFA0 || (cp >= 0xFFF0 && cp <= 0xFFF8)
                || (cp >= 0x1BCA0 && cp <= 0x1BCA3) || (cp >= 0x1D173 && cp <= 0x1D17A)
                || (cp >= 0xE0000 && cp <= 0xE0FFF);
    }

    /** @return the number of columns */
    public int getNx() {
        return nX;
    }

    /** @return the number of rows */
    public int getNy() {
        return nY;
    }

    /** @return the 2024–25 spelling of {@link #getNx()} */
    public int nX() {
        return nX;
    }

    /** @return the 2024–25 spelling of {@link #getNy()} */
    public int nY() {
        return nY;
    }

    /**
     * @return the name given to the constructor, or {@code "(unnamed)"} for a writer made without
     *         one (a camera's lines then show the calling test's name instead, when there is one)
     */
    public String getImageName() {
        return imageName == null ? "(unnamed)" : imageName;
    }

    /** @return whether the writer was made with a name (the 2023–24 form) */
    boolean hasName() {
        return imageName != null;
    }

    /**
     * Sets pixel (column x, row y), clamping each channel to 0..255.
     *
     * @param x     the column, 0 at the left
     * @param y     the row, 0 at the top
     * @param color the pixel's colour
     * @throws IndexOutOfBoundsException naming the pixel when it is outside the image
     */
    public void writePixel(int x, int y, Color color) {
        pixels[index(x, y)] = color.toRgb();
        drawn = true;
    }

    /**
     * Copies a rectangle of packed 0xRRGGBB pixels (as {@link #getRgb} gives them) into the image:
     * a tile rendered elsewhere, by a render worker or a Spark executor. The render loop's workers
     * fill a tile buffer each and copy it here when the tile is done: two workers on neighbouring
     * tiles that stored each pixel into the image as it was done would keep taking the cache line
     * on their common edge from each other (a tile row seldom starts on a line boundary); a bulk
     * copy per finished tile row touches that line once, not once per pixel.
     *
     * @param x      the rectangle's first column
     * @param y      the rectangle's first row
     * @param width  its number of columns, positive
     * @param height its number of rows, positive
     * @param rgb    its pixels, row after row, {@code width} to a row; may be longer
     * @throws IndexOutOfBoundsException naming the rectangle when it does not lie in the image or
     *                                   {@code rgb} is too short for it; nothing is written then
     */
    void writeTile(int x, int y, int width, int height, int[] rgb) {
        if (x < 0 || y < 0 || width <= 0 || height <= 0 || x > nX - width || y > nY - height
                || rgb.length < (long) width * height)
            throw new IndexOutOfBoundsException("tile of " + width + "x" + height + " pixels at (" + x + "," + y
                    + ") with " + rgb.length + " values does not fit the " + nX + "x" + nY + " image");
        for (int row = 0; row < height; ++row) System.arraycopy(rgb, row * width, pixels, (y + row) * nX + x, width);
        drawn = true;
    }

    /**
     * @param x the column, 0 at the left
     * @param y the row, 0 at the top
     * @return pixel (column x, row y) as 0xRRGGBB
     * @throws IndexOutOfBoundsException naming the pixel when it is outside the image
     */
    public int getRgb(int x, int y) {
        return pixels[index(x, y)];
    }

    private int index(int x, int y) {
        if (x < 0 || x >= nX || y < 0 || y >= nY)
            throw new IndexOutOfBoundsException("pixel (" + x + "," + y + ") is outside the " + nX + "x" + nY + " image");
        return y * nX + x;
    }

    /**
     * @return the path {@link #writeToImage()} writes: images/&lt;name&gt;.png
     * @throws IllegalStateException for a writer made without a name
     */
    public Path getPath() {
        if (imageName == null)
            throw new IllegalStateException("this " + nX + "x" + nY + " image writer has no name: use writeToImage(name)");
        return IMAGES.resolve(imageName + ".png");
    }

    /**
     * Writes images/&lt;name&gt;.png, creating folders as needed. Of an image nothing was drawn on
     * (no pixel written), it says so in one line on standard error, and writes the black PNG.
     *
     * @throws IllegalStateException for a writer made without a name
     */
    public void writeToImage() {
        Path file = getPath();
        warnIfBlank(file);
        writeToImage(file);
    }

    /**
     * Writes images/&lt;imageName&gt;.png, creating folders as needed (the 2024–25 course's form;
     * the name given here wins over one given to the constructor). Of an image nothing was drawn
     * on, it says so in one line on standard error, as {@link #writeToImage()} does.
     *
     * @param imageName the file name without ".png"; may contain sub-folders
     * @throws IllegalArgumentException for a blank name
     */
    public void writeToImage(String imageName) {
        Path file = pathOf(imageName);
        warnIfBlank(file);
        writeToImage(file);
    }

    /** A student's own write ({@code Camera} says the same in its write line instead). */
    private void warnIfBlank(Path file) {
        if (!drawn) System.err.println("write " + file + ": " + BLANK);
    }

    /** What a write of an image nothing was drawn on adds to its line. */
    static final String BLANK = "nothing was drawn on this image (no render, grid or writePixel before the write):"
            + " its PNG is all black";

    /** @return whether no pixel was written yet: its PNG would be all black */
    boolean isBlank() {
        return !drawn;
    }

    /** images/&lt;imageName&gt;.png, after checking the name (not blank). */
    static Path pathOf(String imageName) {
        return IMAGES.resolve(checkName(imageName) + ".png");
    }

    /**
     * Writes the PNG to {@code file} atomically: into a temporary file beside it, then moved into
     * place, so a reader never sees a half-written image and a failure leaves no file behind; nor
     * does the JVM's exit during the write (a signal): the temporary file is then deleted.
     * While a JDK Flight Recorder recording runs, the write is a {@code raytracer.ImageWrite}
     * event.
     *
     * @param file where the PNG goes; missing folders are created
     * @throws UncheckedIOException naming the file when it cannot be written, or when the JVM
     *                              exits during the write
     */
    public void writeToImage(Path file) {
        ImageWriteEvent event = ImageEvent.recording() ? new ImageWriteEvent() : null; // see RenderEvent
        // A view of the pixel buffer, not a copy: TYPE_INT_RGB's own layout (0xRRGGBB ints, row
        // by row), so writing needs no second image's worth of memory.
        DirectColorModel rgb = new DirectColorModel(24, 0xFF0000, 0x00FF00, 0x0000FF);
        WritableRaster raster = Raster.createPackedRaster(new DataBufferInt(pixels, pixels.length), nX, nY, nX,
                rgb.getMasks(), null);
        BufferedImage image = new BufferedImage(rgb, raster, false, null);
        Path target = file.toAbsolutePath();
        // SIGINT or SIGTERM while the file is written: the JVM runs its shutdown hooks, and this
        // one abandons the write and deletes the temporary file (see InFlightFile).
        InFlightFile inFlight = new InFlightFile();
        Thread cleanupOnExit = new Thread(inFlight::abandon, "delete the unfinished " + target.getFileName());
        try {
            Runtime.getRuntime().addShutdownHook(cleanupOnExit);
        } catch (IllegalStateException shuttingDown) {
            throw new UncheckedIOException("cannot write image " + target + ": the JVM is shutting down",
                    new IOException(shuttingDown));
        }
        Path tmp = null;
        try {
            Files.createDirectories(target.getParent());
            tmp = InFlightFile.createBeside(target);
            inFlight.created(tmp);
            if (!ImageIO.write(image, "png", tmp.toFile()))
                throw new IOException("no PNG writer available");
            if (!inFlight.mayComplete()) throw new IOException("the JVM is shutting down");
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
            if (event != null) event.commit(imageName, target, nX, nY);
        } catch (IOException e) {
            if (tmp != null) {
                try {
                    Files.deleteIfExists(tmp);
                } catch (IOException cleanup) {
                    e.addSuppressed(cleanup);
                }
            }
            throw new UncheckedIOException("cannot write image " + target + ": " + e.getMessage(), e);
        } finally {
            inFlight.release();
            removeHook(cleanupOnExit, inFlight);
        }
    }

    /**
     * Unregisters a hook; while the JVM shuts down that is refused, and the hook runs (or has run)
     * anyway: running its work here as well is harmless (the writer has released the file, and
     * deleting is idempotent).
     */
    private static void removeHook(Thread hook, InFlightFile inFlight) {
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            inFlight.abandon();
        }
    }
}
