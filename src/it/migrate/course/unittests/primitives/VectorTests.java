package primitives;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import primitives.*;

class VectorTests {
    @Test
    void length() {
        assertEquals(5, new Vector(3, 4, 0).length(), 1e-10);
        assertEquals(new Vector(1, 1, 1), new Point(2, 2, 2).subtract(new Point(1, 1, 1)));
    }
}
