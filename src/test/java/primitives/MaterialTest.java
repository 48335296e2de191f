package primitives;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatIllegalArgumentException;

import java.util.function.BiConsumer;
import java.util.stream.Stream;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

class MaterialTest {

    @Nested
    @DisplayName("fluent setters")
    class Fluent {
        @Test
        void everySetterReturnsTheSameMaterialAndSetsItsField() {
            Material m = new Material();
            assertThat(m.setKd(0.5).setKs(new Double3(0.1, 0.2, 0.3)).setKt(0.25).setKr(new Double3(1, 0, 0.5))
                    .setShininess(30).setReflectionSpread(0.1).setTransmissionSpread(0.2).setIor(1.5)).isSameAs(m);
            assertThat(m.kD).isEqualTo(new Double3(0.5));
            assertThat(m.kS).isEqualTo(new Double3(0.1, 0.2, 0.3));
            assertThat(m.kT).isEqualTo(new Double3(0.25));
            assertThat(m.kR).isEqualTo(new Double3(1, 0, 0.5));
            assertThat(m.nShininess).isEqualTo(30);
            assertThat(m.reflectionSpread).isEqualTo(0.1);
            assertThat(m.transmissionSpread).isEqualTo(0.2);
            assertThat(m.ior).isEqualTo(1.5);
        }

        @Test
        void theIndexOfRefractionDefaultsToOneAndMayBeBelowOne() {
            assertThat(new Material().ior).as("1: the course's straight transmission").isEqualTo(1);
            assertThat(new Material().setIor(0.75).ior).as("a bubble of air in water").isEqualTo(0.75);
        }

        @Test
        void defaultsAreTheCourseDefaults() {
            Material m = new Material();
            assertThat(m.kD).isEqualTo(Double3.ZERO);
            assertThat(m.kS).isEqualTo(Double3.ZERO);
            assertThat(m.kT).isEqualTo(Double3.ZERO);
            assertThat(m.kR).isEqualTo(Double3.ZERO);
            assertThat(m.nShininess).isZero();
        }

        @Test
        @DisplayName("kD and kS may exceed 1; kT and kR may be exactly 0 or 1")
        void boundaryValuesAreAccepted() {
            Material m = new Material().setKd(2).setKs(3).setKt(1).setKr(0);
            assertThat(m.kD).isEqualTo(new Double3(2));
            assertThat(m.kT).isEqualTo(Double3.ONE);
            assertThat(m.kR).isEqualTo(Double3.ZERO);
        }
    }

    /** A named setter taking a Double3, with the field name its message must mention. */
    private record Setter(String name, BiConsumer<Material, Double3> set, boolean atMostOne) {
        @Override
        public String toString() {
            return name;
        }
    }

    private static final Setter[] SETTERS = {
            new Setter("kD", Material::setKd, false),
            new Setter("kS", Material::setKs, false),
            new Setter("kT", Material::setKt, true),
            new Setter("kR", Material::setKr, true),
    };

    static Stream<Arguments> badValues() {
        Stream.Builder<Arguments> b = Stream.builder();
        for (Setter s : SETTERS)
            for (double bad : new double[] { -0.1, Double.NaN, Double.POSITIVE_INFINITY })
                for (int component = 0; component < 3; ++component)
                    b.add(Arguments.of(s, bad, component));
        return b.build();
    }

    @Nested
    @DisplayName("invalid coefficients are rejected naming the coefficient and the value")
    class Rejection {
        @ParameterizedTest(name = "{0} with {1} in component {2}")
        @MethodSource("primitives.MaterialTest#badValues")
        void negativeNaNOrInfinite(Setter setter, double bad, int component) {
            double[] d = { 0.5, 0.5, 0.5 };
            d[component] = bad;
            Double3 value = new Double3(d[0], d[1], d[2]);
            Material m = new Material();
            assertThatIllegalArgumentException().isThrownBy(() -> setter.set.accept(m, value))
                    .withMessageContaining(setter.name).withMessageContaining(String.valueOf(bad));
            assertThat(m.kD).isEqualTo(Double3.ZERO); // nothing half-set
        }

        @ParameterizedTest(name = "{0} above 1")
        @MethodSource("primitives.MaterialTest#transmissive")
        void kTAndKrAboveOneAreRejected(Setter setter) {
            double justAbove = Math.nextUp(1.0);
            assertThatIllegalArgumentException().isThrownBy(() -> setter.set.accept(new Material(), new Double3(0.5, justAbove, 0.5)))
                    .withMessageContaining(setter.name).withMessageContaining(String.valueOf(justAbove));
        }

        @Test
        void scalarSettersAreCheckedToo() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setKd(-1)).withMessageContaining("-1.0");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setKt(1.5)).withMessageContaining("1.5");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setKr(Double.NaN)).withMessageContaining("NaN");
        }

        @ParameterizedTest(name = "ior {0}")
        @ValueSource(doubles = { 0, -0.0, -1.5, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY })
        void anIndexOfRefractionThatIsNotFiniteAndPositiveIsRejected(double ior) {
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setIor(ior))
                    .withMessage("index of refraction must be finite and positive, got " + ior);
        }

        @Test
        void negativeShininessAndSpreadsAreRejected() {
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setShininess(-1))
                    .withMessageContaining("shininess").withMessageContaining("-1");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setReflectionSpread(-0.25))
                    .withMessageContaining("reflection spread").withMessageContaining("-0.25");
            assertThatIllegalArgumentException().isThrownBy(() -> new Material().setTransmissionSpread(Double.NaN))
                    .withMessageContaining("transmission spread").withMessageContaining("NaN");
        }
    }

    static Stream<Setter> transmissive() {
        return Stream.of(SETTERS).filter(Setter::atMostOne);
    }
}
