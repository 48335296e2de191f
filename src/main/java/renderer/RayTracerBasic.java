package renderer;

import geometries.Bvh;
import geometries.Geometry;
import geometries.Hit;
import geometries.Intersectable;
import lighting.LightSource;
import primitives.Color;
import primitives.Double3;
import primitives.Material;
import primitives.Point;
import primitives.Ray;
import primitives.Util;
import primitives.Vector;
import scene.Scene;

/**
 * The Whitted tracer of the course (named {@link SimpleRayTracer} from 2024–25 on): emission,
 * ambient light scaled by the material's {@code kA}, Phong diffuse and specular per
 * light, shadows attenuated by the product of kT of the occluders up to the light, and mirror
 * reflection and (direction-keeping) refraction recursing to {@link #MAX_CALC_COLOR_LEVEL} while
 * the accumulated coefficient stays above {@link #MIN_CALC_COLOR_K}. A material with an index of
 * refraction other than 1 ({@link Material#ior}) bends its transmitted rays instead (Snell's law,
 * total internal reflection, Fresnel).
 *
 * <p>Extensions, each one fluent line and off by default in effect:
 * <ul>
 * <li>{@link #setBvh(boolean)}: the bounding volume hierarchy (on by default; off gives the same
 * image, slower);</li>
 * <li>glossy reflection and diffuse glass, when a material has a non-zero spread: each such
 * bounce traces a beam of {@link #setBeamSize(int)} rays; see {@link #setBeamSize(int)} for the
 * cost policy;</li>
 * <li>soft shadows, when a light has a non-zero radius: {@link #setShadowSamples(int)} shadow
 * rays to points of the light's disk, their transparencies averaged.</li>
 * </ul>
 * Settings are made before rendering; the tracer is then only read, by any number of threads.
 */
public class RayTracerBasic extends RayTracerBase {
    /** The recursion depth limit of reflection and refraction. */
    public static final int MAX_CALC_COLOR_LEVEL = 10;
    /** Below this accumulated coefficient (in every channel) a contribution is not traced. */
    public static final double MIN_CALC_COLOR_K = 0.001;
    private static final Double3 INITIAL_K = Double3.ONE;
    /** The golden-ratio conjugate: spreads beam samples evenly in angle (a Fibonacci lattice). */
    private static final double PHI = 0.6180339887498949;

    private boolean useBvh = true;
    private int beamSize = 16;
    private int shadowSamples = 16;

    /** The scene's geometry as the render queries it (a BVH or the flat list); set by prepare(). */
    private volatile Intersectable world;
    private volatile LightSource[] lights;
    /** What the prepared state was made from, to notice a scene changed between direct calls. */
    private Object preparedGeometries;
    private int preparedItems = -1;
    private int preparedLights = -1;
    /** Scratch for calls of {@link #traceRay(Ray)} made outside a render, one per calling thread. */
    private final ThreadLocal<TraceContext> directContexts =
            ThreadLocal.withInitial(() -> new TraceContext(MAX_CALC_COLOR_LEVEL, MIN_CALC_COLOR_K));

    /**
     * A tracer with the defaults: the BVH on, beams of 16 rays, 16 shadow samples for lights with
     * a radius.
     *
     * @param scene the scene to trace; its BVH is built when a render starts
     */
    public RayTracerBasic(Scene scene) {
        super(scene);
    }

    /**
     * Switches the bounding volume hierarchy on (the default) or off, to compare: both give the
     * same image.
     *
     * @param on whether closest-hit and shadow queries go through the BVH
     * @return this tracer, for chaining
     */
    public RayTracerBasic setBvh(boolean on) {
        this.useBvh = on;
        this.world = null;
        return this;
    }

    /**
     * The number of rays in a glossy-reflection or diffuse-glass beam (default 16).
     * <p>Cost policy: the first glossy or diffuse-glass bounce on the way from the camera traces
     * the full beam; every bounce below a beam traces one ray (drawn from the sample's own random
     * stream). The cost per camera sample thus grows like {@code beamSize × depth}, not
     * {@code beamSize^depth}, and as the beam grows the deeper bounces are averaged over more
     * parents, so the image converges to the same result.
     *
     * @param rays rays per beam, ≥ 1
     * @return this tracer, for chaining
     * @throws IllegalArgumentException when {@code rays < 1}
     */
    public RayTracerBasic setBeamSize(int rays) {
        if (rays < 1) throw new IllegalArgumentException("beam size must be at least 1 ray, got " + rays);
        this.beamSize = rays;
        return this;
    }

    /**
     * The number of shadow rays toward a light with a radius (default 16); lights of radius 0 always
     * use one.
     *
     * @param samples shadow rays per light with a radius and per shaded point, ≥ 1
     * @return this tracer, for chaining
     * @throws IllegalArgumentException when {@code samples < 1}
     */
    public RayTracerBasic setShadowSamples(int samples) {
        if (samples < 1) throw new IllegalArgumentException("shadow samples must be at least 1, got " + samples);
        this.shadowSamples = samples;
        return this;
    }

    /** @return whether queries go through the bounding volume hierarchy */
    public boolean isBvh() {
        return useBvh;
    }

    /** @return rays per glossy or diffuse-glass beam */
    public int getBeamSize() {
        return beamSize;
    }

    /** @return shadow rays toward a light with a radius */
    public int getShadowSamples() {
        return shadowSamples;
    }

    /**
     * Snapshots the scene for tracing: checks every light's settings (before any worker starts,
     * so a bad light fails the render at once with its message) and builds the BVH.
     */
    @Override
    synchronized void prepare() {
        for (LightSource light : scene.lights) light.validate();
        preparedGeometries = scene.geometries;
        preparedItems = scene.geometries.getItems().size();
        preparedLights = scene.lights.size();
        lights = scene.lights.toArray(new LightSource[0]);
        world = useBvh ? Bvh.build(scene.geometries) : scene.geometries;
    }

    /**
     * The prepared geometry for a call outside a render: built on first use, and rebuilt when the
     * scene's geometry list, its number of items or its number of lights changed since (a render
     * always rebuilds; changes deep inside nested {@code Geometries} are seen by the next render).
     */
    private synchronized Intersectable preparedForDirectCall() {
        if (world == null || preparedGeometries != scene.geometries
                || preparedItems != scene.geometries.getItems().size() || preparedLights != scene.lights.size())
            prepare();
        return world;
    }

    @Override
    String describe() {
        return "bvh " + (useBvh ? "on" : "off") + ", beam " + beamSize + ", shadow samples " + shadowSamples;
    }

    /**
     * The colour seen along {@code ray}, for use outside a render (a render calls the tracer
     * through its own loop). Random choices (glossy beams, soft shadows) are keyed by the ray
     * itself, so the same ray always gives the same colour and different rays are independent.
     */
    @Override
    public Color traceRay(Ray ray) {
        preparedForDirectCall();
        TraceContext ctx = directContexts.get();
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        ctx.random.reset(Double.doubleToLongBits(h.getX()) * 31 + Double.doubleToLongBits(h.getY()),
                Double.hashCode(h.getZ()), Double.hashCode(d.getX()) * 31 + Double.hashCode(d.getY()), Double.hashCode(d.getZ()));
        return traceRay(ray, ctx);
    }

    @Override
    Color traceRay(Ray ray, TraceContext ctx) {
        Intersectable w = world;
        Hit hit = ctx.hit(MAX_CALC_COLOR_LEVEL, Double.POSITIVE_INFINITY);
        if (!w.closestHit(ray, hit)) return scene.background;
        Double3 kA = hit.getGeometry().getMaterial().kA; // ambient = I_A·kA(light)·kA(material)
        return calcColor(hit, ray, MAX_CALC_COLOR_LEVEL, INITIAL_K, beamSize, ctx)
                .add(scene.ambientLight.getIntensity().scale(kA));
    }

    /**
     * @param budget rays a glossy beam below this point may use (see {@link #setBeamSize(int)})
     */
    private Color calcColor(Hit hit, Ray ray, int level, Double3 k, int budget, TraceContext ctx) {
        Geometry geometry = hit.getGeometry();
        Point p = hit.point(ray);
        Vector n = hit.normal(p);
        Vector v = ray.getDirection();
        double nv = Util.alignZero(n.dotProduct(v));
        Material material = geometry.getMaterial();
        Color color = geometry.getEmission();
        if (nv != 0) color = color.add(localEffects(p, n, v, nv, material, k, ctx));
        if (level == 1) return color;
        return color.add(globalEffects(p, n, v, nv, material, level, k, budget, ctx));
    }

    private Color localEffects(Point p, Vector n, Vector v, double nv, Material material, Double3 k,
                               TraceContext ctx) {
        // Accumulated in doubles: this runs once per light per hit, the hottest shading code.
        double cr = 0, cg = 0, cb = 0;
        Double3 kd = material.kD, ks = material.kS;
        for (LightSource light : lights) {
            Vector l = light.getL(p);
            double nl = Util.alignZero(n.dotProduct(l));
            if (nl * nv <= 0) continue; // the light is on the other side of the surface from the viewer
            // Phong: kD·|n·l| + kS·max(0, −r·v)^shininess, with r = l − 2(n·l)n.
            double rx = l.getX() - 2 * nl * n.getX(), ry = l.getY() - 2 * nl * n.getY(), rz = l.getZ() - 2 * nl * n.getZ();
            double minusVR = -Util.alignZero(rx * v.getX() + ry * v.getY() + rz * v.getZ());
            double spec = minusVR <= 0 ? 0 : Math.pow(minusVR, material.nShininess);
            double absNl = Math.abs(nl);
            Color iL = light.getIntensity(p);
            double fr = kd.getD1() * absNl + ks.getD1() * spec;
            double fg = kd.getD2() * absNl + ks.getD2() * spec;
            double fb = kd.getD3() * absNl + ks.getD3() * spec;
            // Nothing to shadow (a spot light turned away, a material with kD = kS = 0): the term
            // is exactly zero whatever the occluders, so the shadow walk is not traced.
            if (iL.getR() * fr == 0 && iL.getG() * fg == 0 && iL.getB() * fb == 0) continue;
            Double3 ktr = transparency(p, light, l, n, ctx);
            if (ktr.getD1() * k.getD1() < MIN_CALC_COLOR_K && ktr.getD2() * k.getD2() < MIN_CALC_COLOR_K
                    && ktr.getD3() * k.getD3() < MIN_CALC_COLOR_K) continue;
            cr += iL.getR() * ktr.getD1() * fr;
            cg += iL.getG() * ktr.getD2() * fg;
            cb += iL.getB() * ktr.getD3() * fb;
        }
        return new Color(cr, cg, cb);
    }

    /**
     * The product of kT of the occluders between {@code p} and the light: the course's hard
     * shadow for a point light, or the average over {@link #shadowSamples} points of its disk.
     */
    private Double3 transparency(Point p, LightSource light, Vector l, Vector n, TraceContext ctx) {
        double radius = light.getRadius();
        Intersectable w = world;
        Transmittance tr = ctx.transmittance;
        if (radius == 0) {
            ctx.shadowRays++;
            Hit shadow = ctx.shadow.setRay(p.getX(), p.getY(), p.getZ(), -l.getX(), -l.getY(), -l.getZ(), n.getX(),
                    n.getY(), n.getZ());
            w.visitHits(shadow, light.getDistance(p), tr.reset());
            return tr.r == 1 && tr.g == 1 && tr.b == 1 ? Double3.ONE : new Double3(tr.r, tr.g, tr.b);
        }
        // Soft shadow: stratified points on the disk of the light facing p.
        Point c = light.getPosition();
        Vector toLight = l.negate();
        Vector a = perpendicular(toLight);
        Vector b = toLight.crossProduct(a);
        double side = n.dotProduct(toLight);
        double sr = 0, sg = 0, sb = 0;
        SampleStream rnd = ctx.random;
        double offset = rnd.nextDouble();
        double[] disk = ctx.disk;
        for (int i = 0; i < shadowSamples; ++i) {
            diskPoint(i, shadowSamples, offset, rnd, radius, disk);
            double sx = c.getX() + disk[0] * a.getX() + disk[1] * b.getX();
            double sy = c.getY() + disk[0] * a.getY() + disk[1] * b.getY();
            double sz = c.getZ() + disk[0] * a.getZ() + disk[1] * b.getZ();
            double dx = sx - p.getX(), dy = sy - p.getY(), dz = sz - p.getZ();
            double dist = Math.sqrt(dx * dx + dy * dy + dz * dz);
            // A point of the disk below the surface's horizon sends no light to p.
            if (dist == 0 || (dx * n.getX() + dy * n.getY() + dz * n.getZ()) * side <= 0) continue;
            ctx.shadowRays++;
            w.visitHits(ctx.shadow.setRay(p.getX(), p.getY(), p.getZ(), dx, dy, dz, n.getX(), n.getY(), n.getZ()), dist,
                    tr.reset());
            sr += tr.r;
            sg += tr.g;
            sb += tr.b;
        }
        return new Double3(sr / shadowSamples, sg / shadowSamples, sb / shadowSamples);
    }

    private Color globalEffects(Point p, Vector n, Vector v, double nv, Material material, int level, Double3 k,
                                int budget, TraceContext ctx) {
        if (material.ior != 1 && !material.kT.isZero()) return refraction(p, n, v, nv, material, level, k, budget, ctx);
        Color color = Color.BLACK;
        if (!material.kR.isZero()) { // most materials neither reflect nor transmit: no products then
            Double3 kkr = k.product(material.kR);
            if (!kkr.lowerThan(MIN_CALC_COLOR_K))
                color = color.add(beam(p, n, mirror(v, n, nv), material.reflectionSpread, material.kR, kkr, level, budget, ctx));
        }
        if (!material.kT.isZero()) {
            Double3 kkt = k.product(material.kT);
            if (!kkt.lowerThan(MIN_CALC_COLOR_K))
                color = color.add(beam(p, n, v, material.transmissionSpread, material.kT, kkt, level, budget, ctx));
        }
        return color;
    }

    /** The mirror direction r = v − 2(v·n)n, in one allocation. */
    private static Vector mirror(Vector v, Vector n, double nv) {
        return nv == 0 ? v : new Vector(v.getX() - 2 * nv * n.getX(), v.getY() - 2 * nv * n.getY(), v.getZ() - 2 * nv * n.getZ());
    }

    /**
     * Reflection and transmission of a material with an index of refraction ({@link Material#ior}
     * ≠ 1). Inside and outside are told by the normal: a ray against the normal ({@code v·n < 0})
     * enters the material (from index 1 to {@code ior}), a ray along it leaves (from {@code ior}
     * to 1); there is no stack of media, so a refracting body sits in air and is closed, its
     * normals pointing out. The transmitted ray follows Snell's law; beyond the critical angle it
     * is reflected instead (total internal reflection, with weight kT); when the material reflects
     * (kR &gt; 0) the Fresnel reflectance F (Schlick's approximation, with the cosine on the side of
     * the lower index) moves F·kT from the transmission to the reflection. Reflected light spreads
     * by the reflection spread, transmitted light by the transmission spread.
     */
    private Color refraction(Point p, Vector n, Vector v, double nv, Material material, int level, Double3 k,
                             int budget, TraceContext ctx) {
        double eta = nv < 0 ? 1 / material.ior : material.ior; // n₁ / n₂
        double cosI = Math.abs(nv);
        double cos2T = 1 - eta * eta * (1 - cosI * cosI);
        Double3 kr = material.kR, kt = material.kT;
        Vector t = null;
        if (cos2T <= 0) { // total internal reflection: all the transmitted light is reflected
            kr = kr.add(kt);
            kt = Double3.ZERO;
        } else {
            double cosT = Math.sqrt(cos2T);
            // t = η·v + (η·cosI − cosT)·n', with n' the normal on the incoming side (−sign(v·n)·n).
            double a = (eta * cosI - cosT) * (nv < 0 ? 1 : -1);
            t = new Vector(eta * v.getX() + a * n.getX(), eta * v.getY() + a * n.getY(), eta * v.getZ() + a * n.getZ());
            if (!kr.isZero()) {
                double r0 = (material.ior - 1) / (material.ior + 1);
                r0 *= r0;
                double c = 1 - (eta <= 1 ? cosI : cosT);
                double f = r0 + (1 - r0) * c * c * c * c * c;
                kr = kr.add(kt.scale(f));
                kt = kt.scale(1 - f);
            }
        }
        Color color = Color.BLACK;
        Double3 kkr = k.product(kr);
        if (!kr.isZero() && !kkr.lowerThan(MIN_CALC_COLOR_K))
            color = color.add(beam(p, n, mirror(v, n, nv), material.reflectionSpread, kr, kkr, level, budget, ctx));
        Double3 kkt = k.product(kt);
        if (t != null && !kt.isZero() && !kkt.lowerThan(MIN_CALC_COLOR_K))
            color = color.add(beam(p, n, t, material.transmissionSpread, kt, kkt, level, budget, ctx));
        return color;
    }

    /**
     * One secondary ray along {@code dir}, or, for a spread surface, the average of a beam of rays
     * aimed at a disk of radius {@code spread} at unit distance along {@code dir}, stratified
     * over the disk. A sample that would cross to the wrong side of the surface is mirrored back
     * across it (keeping its weight, so the average neither gains nor loses energy).
     */
    private Color beam(Point p, Vector n, Vector dir, double spread, Double3 kx, Double3 kkx, int level, int budget,
                       TraceContext ctx) {
        if (spread == 0) return secondary(new Ray(p, dir, n), level, kx, kkx, budget, ctx);
        Vector a = perpendicular(dir);
        Vector b = dir.crossProduct(a);
        double side = n.dotProduct(dir);
        SampleStream rnd = ctx.random;
        double offset = rnd.nextDouble();
        double sr = 0, sg = 0, sb = 0;
        double[] disk = ctx.disk;
        for (int i = 0; i < budget; ++i) {
            diskPoint(i, budget, offset, rnd, spread, disk);
            double cx = disk[0], cy = disk[1];
            double dx = dir.getX() + cx * a.getX() + cy * b.getX();
            double dy = dir.getY() + cx * a.getY() + cy * b.getY();
            double dz = dir.getZ() + cx * a.getZ() + cy * b.getZ();
            double dn = dx * n.getX() + dy * n.getY() + dz * n.getZ();
            if (dn * side < 0) {
                dx -= 2 * dn * n.getX();
                dy -= 2 * dn * n.getY();
                dz -= 2 * dn * n.getZ();
            }
            Color c = secondary(new Ray(p, new Vector(dx, dy, dz), n), level, kx, kkx, 1, ctx);
            sr += c.getR();
            sg += c.getG();
            sb += c.getB();
        }
        return new Color(sr / budget, sg / budget, sb / budget);
    }

    private Color secondary(Ray ray, int level, Double3 kx, Double3 kkx, int budget, TraceContext ctx) {
        ctx.secondaryRays++;
        Hit hit = ctx.hit(level - 1, Double.POSITIVE_INFINITY);
        Color c = world.closestHit(ray, hit) ? calcColor(hit, ray, level - 1, kkx, budget, ctx) : scene.background;
        return c.scale(kx);
    }

    /**
     * Point {@code i} of {@code n} stratified over a disk of {@code radius}: stratified in area
     * (radius² uniform within stratum i) and spread in angle by the golden ratio from a random
     * {@code offset}, so any n points cover the disk evenly. Writes the two in-plane coordinates
     * into {@code out}; draws one number from {@code rnd}.
     */
    private static void diskPoint(int i, int n, double offset, SampleStream rnd, double radius, double[] out) {
        double rad = radius * Math.sqrt((i + rnd.nextDouble()) / n);
        double ang = 2 * Math.PI * frac(offset + i * PHI);
        out[0] = rad * Math.cos(ang);
        out[1] = rad * Math.sin(ang);
    }

    /** A unit vector orthogonal to {@code v}. */
    private static Vector perpendicular(Vector v) {
        Vector axis = Math.abs(v.getX()) < 0.9 ? Vector.AXIS_X : Vector.AXIS_Y;
        return v.crossProduct(axis).normalize();
    }

    private static double frac(double x) {
        return x - Math.floor(x);
    }
}
