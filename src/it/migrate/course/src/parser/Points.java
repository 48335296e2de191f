package parser;

import primitives.Point;

public final class Points {
    public static Point parse(String text) {
        String[] p = text.trim().split("\\s+");
        return new Point(Double.parseDouble(p[0]), Double.parseDouble(p[1]), Double.parseDouble(p[2]));
    }
}
