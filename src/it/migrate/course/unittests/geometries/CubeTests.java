package geometries;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import parser.Points;
import primitives.Vector;

class CubeTests {
    @Test
    void normal() {
        assertEquals(new Vector(0, 0, 1), new Cube().getNormal(Points.parse("1 2 3")));
    }
}
