package geometries;

/**
 * Whether a tree's wide nodes are walked yet: while closed, a tree that has them is walked by the
 * scalar walk over its binary nodes (which reads its lane leaves one triangle at a time), and by
 * its {@link WideWalk} once open. It only ever opens. Both walks return the same hits, so the
 * gate changes how fast a ray is answered, never what the answer is: a gate that opens while a
 * render runs changes no pixel.
 *
 * <p>Why a gate: in a fresh JVM the vector walk runs interpreted (its vectors are objects) until
 * the optimizing compiler has compiled it, many times slower than the scalar walk, which would
 * make every short render slower for having the module. The trees of a render share the JVM's
 * own gate, {@link Vectorization#COMPILED}, which {@link VectorWarmUp} opens once the vector
 * code runs compiled; a tree made for a test of the walks holds its own.
 */
final class WideGate {
    /** Always open: for trees whose wide walk is asked for by name (the tests that both walks agree). */
    static final WideGate OPEN = new WideGate(true);

    private volatile boolean open;

    /** @param open whether the wide walk is taken from the start */
    WideGate(boolean open) {
        this.open = open;
    }

    /** @return whether trees behind this gate take their wide walk */
    boolean isOpen() {
        return open;
    }

    /** Lets the trees behind this gate take their wide walk from their next ray on. */
    void open() {
        open = true;
    }
}
