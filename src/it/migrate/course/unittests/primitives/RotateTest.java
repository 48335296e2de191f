package primitives;

import org.junit.jupiter.api.Test;
import primitives.Vector;

class RotateTest {
    @Test
    void rotates() {

        new Vector(1, 0, 0).rotate(90);
    }
}
