package renderer;

import java.lang.annotation.Annotation;
import java.lang.reflect.Method;
import java.util.Optional;
import java.util.Set;

/**
 * Internal, public for {@code renderer.junit} (you never need it): the test method a render runs in, found on the calling thread's stack, to name an image that
 * has no name of its own (the 2024–25 {@code setResolution} + {@code writeToImage(name)} flow,
 * where the name comes only with the write). A frame counts when its method carries one of the
 * test annotations below, compared by name, so the library does not depend on JUnit. The walk
 * stops at the first such frame (a few frames above the render call); anything reflection
 * refuses skips the frame. {@code ImageAssertions} names a camera's failure files after it.
 *
 * @hidden internal: public only for renderer.junit
 */
public final class CallingTest {
    /** The test annotations of JUnit 5 (plain, repeated, parameterized, template), JUnit 4 and TestNG. */
    private static final Set<String> TEST_ANNOTATIONS = Set.of("org.junit.jupiter.api.Test",
            "org.junit.jupiter.api.RepeatedTest", "org.junit.jupiter.api.TestTemplate",
            "org.junit.jupiter.params.ParameterizedTest", "org.junit.Test", "org.testng.annotations.Test");

    private static final StackWalker WALKER = StackWalker.getInstance(StackWalker.Option.RETAIN_CLASS_REFERENCE);

    private CallingTest() {
    }

    /**
     * @return the calling test as {@code Class.method()} (nested classes as {@code Outer.Inner}),
     *         or empty when no frame of the calling thread is a test method (a main method, a
     *         render worker, a dynamic test)
     */
    public static Optional<String> find() {
        return WALKER.walk(frames -> frames.filter(CallingTest::isTest).findFirst())
                .map(f -> simpleName(f.getDeclaringClass()) + "." + f.getMethodName() + "()");
    }

    private static boolean isTest(StackWalker.StackFrame frame) {
        try {
            Method m = frame.getDeclaringClass().getDeclaredMethod(frame.getMethodName(),
                    frame.getMethodType().parameterArray());
            for (Annotation a : m.getDeclaredAnnotations())
                if (TEST_ANNOTATIONS.contains(a.annotationType().getName())) return true;
            return false;
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            return false; // a constructor or initialiser frame, a hidden class, a refused lookup
        }
    }

    /** The class's name without its package, nested classes joined by dots. */
    private static String simpleName(Class<?> c) {
        String name = c.getName();
        return name.substring(name.lastIndexOf('.') + 1).replace('$', '.');
    }
}
