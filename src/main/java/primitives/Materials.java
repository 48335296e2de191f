package primitives;

/**
 * What a render asks of a scene's materials before and after it renders: how often their setters
 * changed them. Apart from {@link Material}, so that a student completing {@code material.} sees
 * the course's setters and fields only; the renderer, in another package, calls this.
 *
 * @hidden internal: the renderer's scene-change check; a scene test sets materials and renders
 */
public final class Materials {
    private Materials() {
    }

    /**
     * @param material a material of a scene's geometry
     * @return how many times its setters gave a coefficient a different value, so far
     */
    public static int changes(Material material) {
        return material.changes();
    }
}
