package primitives;

import static org.junit.Assert.assertEquals;

import org.junit.Test;

/** A JUnit 4 test, as some cohorts wrote them: migrate adds JUnit 4 and the Vintage engine, and it runs. */
public class PointJUnit4Test {
    @Test
    public void length() {
        assertEquals(5, new Point(3, 4, 0).subtract(new Point(0, 0, 0)).length(), 1e-10);
    }
}
