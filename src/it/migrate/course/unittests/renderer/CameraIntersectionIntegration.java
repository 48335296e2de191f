package renderer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import primitives.Vector;

class CameraIntersectionIntegration {
    @Test
    void axis() {
        assertEquals(1, Vector.Z.length(), 1e-10);
    }
}
