package scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatNullPointerException;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import geometries.Geometries;
import geometries.Sphere;
import lighting.AmbientLight;
import lighting.DirectionalLight;
import lighting.LightSource;
import primitives.Color;
import primitives.Point;
import primitives.Vector;

/** The scene is a plain holder the course tests fill through public fields or fluent setters. */
class SceneTest {
    @Test
    @DisplayName("a new scene is empty: black background, no ambient light, no geometries, no lights")
    void defaults() {
        Scene scene = new Scene("empty");
        assertThat(scene.name).isEqualTo("empty");
        assertThat(scene.background.toRgb()).isZero();
        assertThat(scene.ambientLight.getIntensity().toRgb()).isZero();
        assertThat(scene.geometries.isEmpty()).isTrue();
        assertThat(scene.lights).isEmpty();
    }

    @Test
    @DisplayName("the course's style: add to the public geometries and lights")
    void publicFields() {
        Scene scene = new Scene("course");
        Sphere sphere = new Sphere(Point.ZERO, 1);
        DirectionalLight light = new DirectionalLight(new Color(1, 2, 3), new Vector(0, 0, -1));
        scene.geometries.add(sphere);
        scene.lights.add(light);
        assertThat(scene.geometries.getItems()).containsExactly(sphere);
        assertThat(scene.lights).containsExactly(light);
    }

    @Test
    @DisplayName("the fluent setters replace each part and return the scene")
    void fluentSetters() {
        Geometries geometries = new Geometries(new Sphere(Point.ZERO, 2));
        List<LightSource> lights = new ArrayList<>();
        AmbientLight ambient = new AmbientLight(new Color(10, 20, 30), 1);
        Scene scene = new Scene("fluent");
        assertThat(scene.setBackground(new Color(5, 6, 7)).setAmbientLight(ambient).setGeometries(geometries)
                .setLights(lights)).isSameAs(scene);
        assertThat(scene.background.toRgb()).isEqualTo(0x050607);
        assertThat(scene.ambientLight).isSameAs(ambient);
        assertThat(scene.geometries).isSameAs(geometries);
        assertThat(scene.lights).isSameAs(lights);
    }

    @Test
    @DisplayName("scenes do not share their lists")
    void independentScenes() {
        Scene a = new Scene("a"), b = new Scene("b");
        a.geometries.add(new Sphere(Point.ZERO, 1));
        a.lights.add(new DirectionalLight(new Color(1, 1, 1), new Vector(0, 0, -1)));
        assertThat(b.geometries.isEmpty()).isTrue();
        assertThat(b.lights).isEmpty();
    }

    @Test
    @DisplayName("null parts are rejected, naming the part")
    void nulls() {
        Scene scene = new Scene("nulls");
        assertThatNullPointerException().isThrownBy(() -> new Scene(null)).withMessageContaining("name");
        assertThatNullPointerException().isThrownBy(() -> scene.setBackground(null)).withMessageContaining("background");
        assertThatNullPointerException().isThrownBy(() -> scene.setAmbientLight(null)).withMessageContaining("ambient");
        assertThatNullPointerException().isThrownBy(() -> scene.setGeometries(null)).withMessageContaining("geometries");
        assertThatNullPointerException().isThrownBy(() -> scene.setLights(null)).withMessageContaining("lights");
    }
}
