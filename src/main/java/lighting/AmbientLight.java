package lighting;

import java.util.Objects;

import primitives.Color;
import primitives.Double3;

/** The uniform background illumination: a colour scaled by an attenuation factor kA. */
public class AmbientLight extends Light {
    /** No ambient light at all. */
    public static final AmbientLight NONE = new AmbientLight(Color.BLACK, 0);

    /**
     * @param iA the ambient colour before attenuation
     * @param kA per-channel factor, each finite and ≥ 0; the light is {@code iA·kA}
     * @throws IllegalArgumentException when a factor is negative or not finite
     */
    public AmbientLight(Color iA, Double3 kA) {
        super(Objects.requireNonNull(iA, "ambient intensity").scale(Objects.requireNonNull(kA, "ambient factor kA")));
    }

    /**
     * The 2024–25 form: the light as it is, its attenuation now being the material's
     * {@link primitives.Material#kA} (the two compose: both default to 1).
     *
     * @param iA the ambient intensity
     * @throws NullPointerException when iA is null
     */
    public AmbientLight(Color iA) {
        this(Objects.requireNonNull(iA, "ambient intensity"), Double3.ONE);
    }

    /**
     * @param iA the ambient colour before attenuation
     * @param kA the factor of all three channels, finite and ≥ 0; the light is {@code iA·kA}
     * @throws IllegalArgumentException when the factor is negative or not finite
     */
    public AmbientLight(Color iA, double kA) {
        super(Objects.requireNonNull(iA, "ambient intensity").scale(kA));
    }
}
