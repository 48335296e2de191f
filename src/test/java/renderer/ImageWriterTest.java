package renderer;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Comparator;
import java.util.Random;
import java.util.UUID;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import primitives.Color;

/** The pixel buffer and its PNG file. */
class ImageWriterTest {
    @Nested
    @DisplayName("construction")
    class Construction {
        @ParameterizedTest(name = "{0}x{1}")
        @CsvSource({"0, 5", "5, 0", "-1, 5", "5, -3", "0, 0"})
        @DisplayName("a non-positive size is rejected with the size in the message")
        void nonPositiveSize(int nX, int nY) {
            assertThatIllegalArgumentException().isThrownBy(() -> new ImageWriter("bad", nX, nY))
                    .withMessageContaining(nX + "x" + nY);
        }

        @Test
        @DisplayName("a blank or null name is rejected")
        void blankName() {
            assertThatIllegalArgumentException().isThrownBy(() -> new ImageWriter("  ", 1, 1));
            assertThatThrownBy(() -> new ImageWriter(null, 1, 1)).isInstanceOf(NullPointerException.class);
        }

        @Test
        @DisplayName("nX is the number of columns, nY the number of rows")
        void dimensions() {
            ImageWriter image = new ImageWriter("dims", 7, 3);
            assertThat(image.getNx()).isEqualTo(7);
            assertThat(image.getNy()).isEqualTo(3);
            image.writePixel(6, 2, new Color(1, 2, 3)); // the last pixel exists
            assertThatThrownBy(() -> image.writePixel(2, 6, Color.BLACK)).isInstanceOf(IndexOutOfBoundsException.class)
                    .hasMessageContaining("(2,6)");
        }
    }

    @Nested
    @DisplayName("pixels")
    class PixelBuffer {
        @Test
        @DisplayName("pixels start black and keep what was written, each channel truncated and clamped to 0..255")
        void writeAndRead() {
            ImageWriter image = new ImageWriter("pixels", 3, 2);
            assertThat(image.getRgb(2, 1)).isZero();
            image.writePixel(2, 1, new Color(12.9, 300, 0.5));
            image.writePixel(0, 1, new Color(255, 0, 128));
            assertThat(image.getRgb(2, 1)).isEqualTo(0x0CFF00);
            assertThat(image.getRgb(0, 1)).isEqualTo(0xFF0080);
            assertThat(image.getRgb(1, 0)).isZero();
        }

        @ParameterizedTest(name = "{2}x{3} at ({0},{1})")
        @CsvSource({"0, 0, 7, 5", "2, 1, 3, 2", "6, 4, 1, 1", "4, 0, 3, 5", "0, 3, 7, 2"})
        @DisplayName("a tile lands row by row in its rectangle, and the pixels around it stay as they were")
        void tile(int x, int y, int width, int height) {
            ImageWriter image = new ImageWriter("tile", 7, 5);
            for (int j = 0; j < 5; ++j)
                for (int i = 0; i < 7; ++i) image.writePixel(i, j, new Color(1, 1, 1));
            int[] rgb = new int[width * height + 3]; // a buffer may be longer than its tile
            for (int k = 0; k < rgb.length; ++k) rgb[k] = 0x100000 + k;
            image.writeTile(x, y, width, height, rgb);
            for (int j = 0; j < 5; ++j)
                for (int i = 0; i < 7; ++i) {
                    boolean inside = i >= x && i < x + width && j >= y && j < y + height;
                    assertThat(image.getRgb(i, j)).as("pixel (%d,%d)", i, j)
                            .isEqualTo(inside ? 0x100000 + (j - y) * width + (i - x) : 0x010101);
                }
        }

        @ParameterizedTest(name = "{2}x{3} at ({0},{1}) from {4} values")
        @CsvSource({"-1, 0, 2, 2, 4", "0, -1, 2, 2, 4", "6, 0, 2, 1, 2", "0, 4, 1, 2, 2", "0, 0, 0, 1, 4",
                "0, 0, 1, 0, 4", "0, 0, 2, 2, 3", "2147483647, 0, 2, 1, 2"})
        @DisplayName("a tile that does not fit the image, or a buffer too short for it, is refused, naming both")
        void tileOutside(int x, int y, int width, int height, int values) {
            ImageWriter image = new ImageWriter("tile", 7, 5);
            int[] rgb = new int[values];
            Arrays.fill(rgb, 0x123456);
            assertThatThrownBy(() -> image.writeTile(x, y, width, height, rgb))
                    .isInstanceOf(IndexOutOfBoundsException.class)
                    .hasMessageContaining(width + "x" + height + " pixels at (" + x + "," + y + ")")
                    .hasMessageContaining(values + " values").hasMessageContaining("7x5 image");
            for (int j = 0; j < 5; ++j)
                for (int i = 0; i < 7; ++i) assertThat(image.getRgb(i, j)).as("pixel (%d,%d): nothing written", i, j).isZero();
        }
    }

    @Nested
    @DisplayName("an image nothing was drawn on")
    class Blank {
        @Test
        @DisplayName("is blank until a pixel or a tile is written")
        void blankUntilDrawn() {
            ImageWriter byPixel = new ImageWriter("blank", 3, 2);
            assertThat(byPixel.isBlank()).isTrue();
            byPixel.writePixel(2, 1, new primitives.Color(0, 0, 0)); // black, but drawn
            assertThat(byPixel.isBlank()).isFalse();
            ImageWriter byTile = new ImageWriter("blank", 3, 2);
            byTile.writeTile(0, 0, 1, 1, new int[] { 0 });
            assertThat(byTile.isBlank()).isFalse();
        }
    }

    @Nested
    @DisplayName("writing the PNG")
    class Writing {
        /** A folder under images/ no other test uses; deleted after each test. */
        private final String folder = "rtests-" + UUID.randomUUID();
        private final Path folderPath = ImageWriter.IMAGES.resolve(folder);

        @AfterEach
        void deleteFolder() throws IOException {
            if (!Files.exists(folderPath)) return;
            try (Stream<Path> files = Files.walk(folderPath)) {
                for (Path p : files.sorted(Comparator.reverseOrder()).toList()) Files.delete(p);
            }
        }

        @Test
        @DisplayName("creates images/<sub-folder> when missing and writes the pixels")
        void createsFolder() throws IOException {
            assertThat(folderPath).doesNotExist();
            ImageWriter image = new ImageWriter(folder + "/nested/picture", 3, 2);
            image.writePixel(0, 0, new Color(255, 0, 0));
            image.writePixel(2, 1, new Color(0, 0, 255));
            image.writePixel(1, 0, new Color(10, 20, 30));
            image.writeToImage();

            Path file = folderPath.resolve("nested/picture.png");
            assertThat(image.getPath()).isEqualTo(file);
            assertThat(file).isRegularFile();
            BufferedImage read = ImageIO.read(file.toFile());
            assertThat(read.getWidth()).isEqualTo(3);
            assertThat(read.getHeight()).isEqualTo(2);
            assertThat(read.getRGB(0, 0) & 0xFFFFFF).isEqualTo(0xFF0000);
            assertThat(read.getRGB(2, 1) & 0xFFFFFF).isEqualTo(0x0000FF);
            assertThat(read.getRGB(1, 0) & 0xFFFFFF).isEqualTo(0x0A141E);
            assertThat(read.getRGB(0, 1) & 0xFFFFFF).isZero();
            assertNoTemporaryFiles(file.getParent());
        }

        /**
         * The writer hands ImageIO a view of its pixel buffer rather than a copy (so that writing
         * needs no second image's worth of memory); the file must be what ImageIO writes for a
         * TYPE_INT_RGB copy of the same pixels.
         */
        @Test
        @DisplayName("the PNG is byte for byte the one of a TYPE_INT_RGB copy of the pixels")
        void sameBytesAsCopy(@TempDir Path dir) throws IOException {
            int nX = 37, nY = 23;
            Random random = new Random(42);
            ImageWriter image = new ImageWriter("any", nX, nY);
            BufferedImage copy = new BufferedImage(nX, nY, BufferedImage.TYPE_INT_RGB);
            for (int y = 0; y < nY; ++y)
                for (int x = 0; x < nX; ++x) {
                    Color color = new Color(random.nextInt(256), random.nextInt(256), random.nextInt(256));
                    image.writePixel(x, y, color);
                    copy.setRGB(x, y, color.toRgb());
                }
            Path file = dir.resolve("view.png");
            image.writeToImage(file);
            ByteArrayOutputStream expected = new ByteArrayOutputStream();
            assertThat(ImageIO.write(copy, "png", expected)).isTrue();
            assertThat(Files.readAllBytes(file)).isEqualTo(expected.toByteArray());
        }

        @Test
        @DisplayName("writing again replaces the file")
        void replaces() throws IOException {
            ImageWriter image = new ImageWriter(folder + "/again", 1, 1);
            image.writeToImage();
            image.writePixel(0, 0, new Color(0, 255, 0));
            image.writeToImage();
            assertThat(ImageIO.read(image.getPath().toFile()).getRGB(0, 0) & 0xFFFFFF).isEqualTo(0x00FF00);
            assertNoTemporaryFiles(folderPath);
        }

        @Test
        @DisplayName("a failing write throws UncheckedIOException naming the path and leaves no temporary file")
        void failingWrite() throws IOException {
            // The target images/<folder>/blocked.png is a (non-empty) directory: the final move must fail.
            Path blocked = Files.createDirectories(folderPath.resolve("blocked.png"));
            Files.writeString(blocked.resolve("keep.txt"), "occupied");
            ImageWriter image = new ImageWriter(folder + "/blocked", 2, 2);

            assertThatThrownBy(image::writeToImage).isInstanceOf(UncheckedIOException.class)
                    .hasMessageContaining(blocked.toAbsolutePath().toString());
            assertNoTemporaryFiles(folderPath);
            assertThat(blocked).isDirectory();
            assertThat(blocked.resolve("keep.txt")).hasContent("occupied");
        }

        private void assertNoTemporaryFiles(Path dir) throws IOException {
            try (Stream<Path> files = Files.list(dir)) {
                assertThat(files.map(p -> p.getFileName().toString()))
                        .as("files left in %s", dir).noneMatch(n -> n.endsWith(".tmp") || n.startsWith("."));
            }
        }
    }
}
