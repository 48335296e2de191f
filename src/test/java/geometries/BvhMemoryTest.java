package geometries;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

/**
 * The BVH build's memory check, on made-up heaps (no test allocates gigabytes): a build that
 * cannot fit is refused before its first array, in one line naming the primitives, the memory
 * needed, the limit, what was free and the remedies.
 */
class BvhMemoryTest {
    private static final long MB = 1 << 20;

    @Test
    @DisplayName("the issue's mesh: 4.5 million triangles with -Xmx1200m and 300 MB held elsewhere is refused at once")
    void refused() {
        assertThatThrownBy(() -> BvhBuilder.requireMemory(4_500_000, 1, 1200 * MB, 300 * MB))
                .isInstanceOf(OutOfMemoryError.class)
                .hasMessage("the BVH over 4500000 primitives needs about 996 MB; Java may use at most 1200 MB here, of"
                        + " which about 900 MB were free (give Java more memory with -Xmx, on a Spark executor"
                        + " --executor-memory; or render without the BVH: setBvh(false), <render bvh=\"false\">)");
    }

    @Test
    @DisplayName("a build that fits, or a heap without a limit, goes ahead")
    void fits() {
        assertThatCode(() -> BvhBuilder.requireMemory(4_500_000, 1, 1500 * MB, 300 * MB)).doesNotThrowAnyException();
        assertThatCode(() -> BvhBuilder.requireMemory(4_500_000, 1, Long.MAX_VALUE, 300 * MB)).doesNotThrowAnyException();
    }

    @Test
    @DisplayName("the estimate: 232 bytes a primitive (slots, partition scratch, node slots) and 57 a shape")
    void estimate() {
        assertThat(BvhBuilder.bytesNeeded(1_000_000, 1)).isEqualTo(232_000_057L);
        assertThat(BvhBuilder.bytesNeeded(1000, 1000)).isEqualTo(289_000L);
    }
}
