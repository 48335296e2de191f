package renderer;

import primitives.Vector;

public class Turner {
    public static Vector quarter(Vector v) { return v.rotate(90); }
}
