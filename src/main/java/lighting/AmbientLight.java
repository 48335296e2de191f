package lighting;

import primitives.Color;
import primitives.Double3;

/** The uniform background illumination: a colour scaled by an attenuation factor kA. */
public class AmbientLight extends Light {
    /** No ambient light at all. */
    public static final AmbientLight NONE = new AmbientLight(Color.BLACK, 0);

    /** @param kA per-channel factor, each ≥ 0 */
    public AmbientLight(Color iA, Double3 kA) {
        super(iA.scale(kA));
    }

    /** @param kA factor ≥ 0 */
    public AmbientLight(Color iA, double kA) {
        super(iA.scale(kA));
    }
}
