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
    /** The golden-ratio conjugate: spreads beam samples evenly in angle (a Fibonacci lattice). */
    private static final double PHI = 0.6180339887498949;

    private boolean useBvh = true;
    private int beamSize = 16;
    private int shadowSamples = 16;

    /** The scene's geometry as the render queries it (a BVH or the flat list); set by prepare(). */
    private volatile Intersectable world;
    private volatile LightSource[] lights;
    /** Scratch for calls of {@link #traceRay(Ray)} made outside a render, one per calling thread. */
    private final ThreadLocal<TraceContext> directContexts =
            ThreadLocal.withInitial(this::newContext);

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
        forgetPreparation();
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
     * Snapshots the scene for tracing: checks the nesting of its geometries
     * ({@link geometries.Geometries#MAX_NESTING_DEPTH}) and every light's settings (before any
     * worker starts, so a bad scene fails the render at once with its message) and builds the BVH, or reuses the
     * one an earlier render built over the same, unchanged shapes ({@link Bvh#of}).
     */
    @Override
    synchronized void prepare() {
        scene.geometries.requireNestingWithinLimit(); // the flat walk recurses once per level
        for (LightSource light : scene.lights) light.validate();
        lights = scene.lights.toArray(new LightSource[0]);
        world = useBvh ? Bvh.of(scene.geometries) : scene.geometries;
    }

    @Override
    TraceContext newContext() {
        return new TraceContext(MAX_CALC_COLOR_LEVEL, MIN_CALC_COLOR_K);
    }

    @Override
    void requireRayBudget(AntiAliasing mode, long cameraRays) {
        RayBudget.require(mode, cameraRays, beamSize, shadowSamples);
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
        prepareIfChanged();
        TraceContext ctx = directContexts.get();
        Point h = ray.getHead();
        Vector d = ray.getDirection();
        ctx.random.reset(Double.doubleToLongBits(h.getX()) * 31 + Double.doubleToLongBits(h.getY()),
                Double.hashCode(h.getZ()), Double.hashCode(d.getX()) * 31 + Double.hashCode(d.getY()), Double.hashCode(d.getZ()));
        ctx.cameraRay().setRay(h.getX(), h.getY(), h.getZ(), d.getX(), d.getY(), d.getZ());
        traceRay(ctx);
        return new Color(ctx.r, ctx.g, ctx.b);
    }

    /*
     * The tracing core keeps every ray, point, normal, colour and coefficient in doubles: a ray
     * lives in its level's Hit record, colours are returned through the context's per-level
     * slots (red/green/blue[level]), coefficients k are passed as three doubles. The arithmetic
     * is the object code's, operation for operation (Color.add and scale, Double3.product,
     * Ray's normalization and head offset through the shared primitives helpers), so images are
     * bit-identical to what Ray/Point/Vector/Color objects would give; nothing is allocated per
     * ray for the library's geometries and lights.
     */

    @Override
    void traceRay(TraceContext ctx) {
        ctx.stopIfInterrupted(); // a pixel may take 65,536 camera samples
        Hit hit = ctx.hit(MAX_CALC_COLOR_LEVEL, Double.POSITIVE_INFINITY); // the camera ray's record
        if (!world.closestHit(hit)) {
            Color bg = scene.background;
            ctx.r = bg.getR();
            ctx.g = bg.getG();
            ctx.b = bg.getB();
            return;
        }
        Double3 kA = hit.getGeometry().getMaterial().kA; // ambient = I_A·kA(light)·kA(material)
        calcColor(hit, MAX_CALC_COLOR_LEVEL, 1, 1, 1, beamSize, ctx);
        Color ambient = scene.ambientLight.getIntensity();
        int top = MAX_CALC_COLOR_LEVEL;
        ctx.r = ctx.red[top] + ambient.getR() * kA.getD1();
        ctx.g = ctx.green[top] + ambient.getG() * kA.getD2();
        ctx.b = ctx.blue[top] + ambient.getB() * kA.getD3();
    }

    /**
     * The colour at the hit of {@code hit} (found by a closest-hit query of its ray), into slot
     * {@code level}.
     *
     * @param kr     the accumulated coefficient's red (with kg, kb: the path's product of kR/kT)
     * @param budget rays a glossy beam below this point may use (see {@link #setBeamSize(int)})
     */
    private void calcColor(Hit hit, int level, double kr, double kg, double kb, int budget, TraceContext ctx) {
        Geometry geometry = hit.getGeometry();
        hit.computeSurface();
        double nv = Util.alignZero(hit.normalX() * hit.directionX() + hit.normalY() * hit.directionY()
                + hit.normalZ() * hit.directionZ());
        Material material = geometry.getMaterial();
        Color emission = geometry.getEmission();
        double r = emission.getR(), g = emission.getG(), b = emission.getB();
        if (nv != 0) {
            localEffects(hit, nv, material, kr, kg, kb, ctx);
            double[] local = ctx.local;
            r = r + local[0];
            g = g + local[1];
            b = b + local[2];
        }
        if (level != 1) {
            globalEffects(hit, nv, material, level, kr, kg, kb, budget, ctx);
            r = r + ctx.red[level];
            g = g + ctx.green[level];
            b = b + ctx.blue[level];
        }
        ctx.red[level] = r;
        ctx.green[level] = g;
        ctx.blue[level] = b;
    }

    /** Emission aside, the light arriving directly: Phong per light, times its shadow transparency; into ctx.local. */
    private void localEffects(Hit hit, double nv, Material material, double kr, double kg, double kb,
                              TraceContext ctx) {
        // Accumulated in doubles: this runs once per light per hit, the hottest shading code.
        double cr = 0, cg = 0, cb = 0;
        Double3 kd = material.kD, ks = material.kS;
        double px = hit.pointX(), py = hit.pointY(), pz = hit.pointZ();
        double nx = hit.normalX(), ny = hit.normalY(), nz = hit.normalZ();
        double vx = hit.directionX(), vy = hit.directionY(), vz = hit.directionZ();
        double[] l = ctx.light, iL = ctx.intensity, ktr = ctx.transparency;
        LightSource[] lights = this.lights;
        for (int li = 0; li < lights.length; ++li) {
            LightSource light = lights[li];
            light.getL(px, py, pz, l);
            double lx = l[0], ly = l[1], lz = l[2];
            double nl = Util.alignZero(nx * lx + ny * ly + nz * lz);
            if (nl * nv <= 0) continue; // the light is on the other side of the surface from the viewer
            // Phong: kD·|n·l| + kS·max(0, −r·v)^shininess, with r = l − 2(n·l)n.
            double rx = lx - 2 * nl * nx, ry = ly - 2 * nl * ny, rz = lz - 2 * nl * nz;
            double minusVR = -Util.alignZero(rx * vx + ry * vy + rz * vz);
            double spec = minusVR <= 0 ? 0 : Math.pow(minusVR, material.nShininess);
            double absNl = Math.abs(nl);
            light.getIntensity(px, py, pz, iL);
            double ir = iL[0], ig = iL[1], ib = iL[2];
            double fr = kd.getD1() * absNl + ks.getD1() * spec;
            double fg = kd.getD2() * absNl + ks.getD2() * spec;
            double fb = kd.getD3() * absNl + ks.getD3() * spec;
            // Nothing to shadow (a spot light turned away, a material with kD = kS = 0): the term
            // is exactly zero whatever the occluders, so the shadow walk is not traced.
            if (ir * fr == 0 && ig * fg == 0 && ib * fb == 0) continue;
            transparency(hit, light, li, lx, ly, lz, ctx);
            if (ktr[0] * kr < MIN_CALC_COLOR_K && ktr[1] * kg < MIN_CALC_COLOR_K
                    && ktr[2] * kb < MIN_CALC_COLOR_K) continue;
            cr += ir * ktr[0] * fr;
            cg += ig * ktr[1] * fg;
            cb += ib * ktr[2] * fb;
        }
        double[] local = ctx.local;
        local[0] = cr;
        local[1] = cg;
        local[2] = cb;
    }

    /**
     * The product of kT of the occluders between the hit point and the light (whose unit
     * direction toward the point is l), into ctx.transparency: the course's hard shadow for a
     * point light, or the average over {@link #shadowSamples} points of its disk.
     */
    private void transparency(Hit hit, LightSource light, int li, double lx, double ly, double lz, TraceContext ctx) {
        double radius = light.getRadius();
        Intersectable w = world;
        Transmittance tr = ctx.transmittance;
        ShadowCache cache = ctx.shadowCache;
        double px = hit.pointX(), py = hit.pointY(), pz = hit.pointZ();
        double nx = hit.normalX(), ny = hit.normalY(), nz = hit.normalZ();
        double[] ktr = ctx.transparency;
        if (radius == 0) {
            ctx.shadowRays++;
            cache.trace(w, ctx.shadow.setRay(px, py, pz, -lx, -ly, -lz, nx, ny, nz), light.getDistance(px, py, pz), li, tr);
            ktr[0] = tr.r;
            ktr[1] = tr.g;
            ktr[2] = tr.b;
            return;
        }
        // Soft shadow: stratified points on the disk of the light facing p.
        Point c = light.getPosition();
        double tx = -lx, ty = -ly, tz = -lz; // toward the light
        double[] basis = ctx.vector;
        perpendicular(tx, ty, tz, basis);
        double ax = basis[0], ay = basis[1], az = basis[2];
        Vector.crossProduct(tx, ty, tz, ax, ay, az, basis);
        double bx = basis[0], by = basis[1], bz = basis[2];
        double side = nx * tx + ny * ty + nz * tz;
        double sr = 0, sg = 0, sb = 0;
        SampleStream rnd = ctx.random;
        double offset = rnd.nextDouble();
        double[] disk = ctx.disk;
        for (int i = 0; i < shadowSamples; ++i) {
            ctx.stopIfInterrupted(); // a soft shadow may take millions of rays
            diskPoint(i, shadowSamples, offset, rnd, radius, disk);
            double sx = c.getX() + disk[0] * ax + disk[1] * bx;
            double sy = c.getY() + disk[0] * ay + disk[1] * by;
            double sz = c.getZ() + disk[0] * az + disk[1] * bz;
            double dx = sx - px, dy = sy - py, dz = sz - pz;
            double dist = Math.sqrt(dx * dx + dy * dy + dz * dz);
            // A point of the disk below the surface's horizon sends no light to p.
            if (dist == 0 || (dx * nx + dy * ny + dz * nz) * side <= 0) continue;
            ctx.shadowRays++;
            cache.trace(w, ctx.shadow.setRay(px, py, pz, dx, dy, dz, nx, ny, nz), dist, li, tr);
            sr += tr.r;
            sg += tr.g;
            sb += tr.b;
        }
        ktr[0] = sr / shadowSamples;
        ktr[1] = sg / shadowSamples;
        ktr[2] = sb / shadowSamples;
    }

    /** Reflection and transmission, into slot {@code level}. */
    private void globalEffects(Hit hit, double nv, Material material, int level, double kr, double kg, double kb,
                               int budget, TraceContext ctx) {
        if (material.ior != 1 && !material.kT.isZero()) {
            refraction(hit, nv, material, level, kr, kg, kb, budget, ctx);
            return;
        }
        double r = 0, g = 0, b = 0; // Color.BLACK, added to as the object code did
        Double3 kR = material.kR, kT = material.kT;
        if (!kR.isZero()) { // most materials neither reflect nor transmit: no products then
            double kkr = kr * kR.getD1(), kkg = kg * kR.getD2(), kkb = kb * kR.getD3();
            if (!lowerThanMin(kkr, kkg, kkb)) {
                mirrorBeam(hit, nv, material.reflectionSpread, kR.getD1(), kR.getD2(), kR.getD3(), kkr, kkg, kkb,
                        level, budget, ctx);
                r = r + ctx.red[level];
                g = g + ctx.green[level];
                b = b + ctx.blue[level];
            }
        }
        if (!kT.isZero()) {
            double kkr = kr * kT.getD1(), kkg = kg * kT.getD2(), kkb = kb * kT.getD3();
            if (!lowerThanMin(kkr, kkg, kkb)) {
                beam(hit, hit.directionX(), hit.directionY(), hit.directionZ(), material.transmissionSpread,
                        kT.getD1(), kT.getD2(), kT.getD3(), kkr, kkg, kkb, level, budget, ctx);
                r = r + ctx.red[level];
                g = g + ctx.green[level];
                b = b + ctx.blue[level];
            }
        }
        ctx.red[level] = r;
        ctx.green[level] = g;
        ctx.blue[level] = b;
    }

    /** Double3.lowerThan(MIN_CALC_COLOR_K) of (r, g, b). */
    private static boolean lowerThanMin(double r, double g, double b) {
        return r < MIN_CALC_COLOR_K && g < MIN_CALC_COLOR_K && b < MIN_CALC_COLOR_K;
    }

    /** {@link #beam} along the mirror direction r = v − 2(v·n)n of the hit's ray. */
    private void mirrorBeam(Hit hit, double nv, double spread, double kxr, double kxg, double kxb, double kkr,
                            double kkg, double kkb, int level, int budget, TraceContext ctx) {
        double vx = hit.directionX(), vy = hit.directionY(), vz = hit.directionZ();
        if (nv != 0) {
            vx = vx - 2 * nv * hit.normalX();
            vy = vy - 2 * nv * hit.normalY();
            vz = vz - 2 * nv * hit.normalZ();
        }
        beam(hit, vx, vy, vz, spread, kxr, kxg, kxb, kkr, kkg, kkb, level, budget, ctx);
    }

    /**
     * Reflection and transmission of a material with an index of refraction ({@link Material#ior}
     * ≠ 1), into slot {@code level}. Inside and outside are told by the normal: a ray against the
     * normal ({@code v·n < 0}) enters the material (from index 1 to {@code ior}), a ray along it
     * leaves (from {@code ior} to 1); there is no stack of media, so a refracting body sits in air
     * and is closed, its normals pointing out. The transmitted ray follows Snell's law; beyond the
     * critical angle it is reflected instead (total internal reflection, with weight kT); when the
     * material reflects (kR &gt; 0) the Fresnel reflectance F (Schlick's approximation, with the
     * cosine on the side of the lower index) moves F·kT from the transmission to the reflection.
     * Reflected light spreads by the reflection spread, transmitted light by the transmission spread.
     */
    private void refraction(Hit hit, double nv, Material material, int level, double kr, double kg, double kb,
                            int budget, TraceContext ctx) {
        double eta = nv < 0 ? 1 / material.ior : material.ior; // n₁ / n₂
        double cosI = Math.abs(nv);
        double cos2T = 1 - eta * eta * (1 - cosI * cosI);
        double rr = material.kR.getD1(), rg = material.kR.getD2(), rb = material.kR.getD3();
        double tr = material.kT.getD1(), tg = material.kT.getD2(), tb = material.kT.getD3();
        boolean transmits = false;
        double tx = 0, ty = 0, tz = 0;
        if (cos2T <= 0) { // total internal reflection: all the transmitted light is reflected
            rr = rr + tr;
            rg = rg + tg;
            rb = rb + tb;
            tr = tg = tb = 0;
        } else {
            double cosT = Math.sqrt(cos2T);
            // t = η·v + (η·cosI − cosT)·n', with n' the normal on the incoming side (−sign(v·n)·n).
            double a = (eta * cosI - cosT) * (nv < 0 ? 1 : -1);
            tx = eta * hit.directionX() + a * hit.normalX();
            ty = eta * hit.directionY() + a * hit.normalY();
            tz = eta * hit.directionZ() + a * hit.normalZ();
            transmits = true;
            if (!(rr == 0 && rg == 0 && rb == 0)) {
                double r0 = (material.ior - 1) / (material.ior + 1);
                r0 *= r0;
                double c = 1 - (eta <= 1 ? cosI : cosT);
                double f = r0 + (1 - r0) * c * c * c * c * c;
                rr = rr + tr * f;
                rg = rg + tg * f;
                rb = rb + tb * f;
                tr = tr * (1 - f);
                tg = tg * (1 - f);
                tb = tb * (1 - f);
            }
        }
        double r = 0, g = 0, b = 0; // Color.BLACK, added to as the object code did
        double kkr = kr * rr, kkg = kg * rg, kkb = kb * rb;
        if (!(rr == 0 && rg == 0 && rb == 0) && !lowerThanMin(kkr, kkg, kkb)) {
            mirrorBeam(hit, nv, material.reflectionSpread, rr, rg, rb, kkr, kkg, kkb, level, budget, ctx);
            r = r + ctx.red[level];
            g = g + ctx.green[level];
            b = b + ctx.blue[level];
        }
        kkr = kr * tr;
        kkg = kg * tg;
        kkb = kb * tb;
        if (transmits && !(tr == 0 && tg == 0 && tb == 0) && !lowerThanMin(kkr, kkg, kkb)) {
            beam(hit, tx, ty, tz, material.transmissionSpread, tr, tg, tb, kkr, kkg, kkb, level, budget, ctx);
            r = r + ctx.red[level];
            g = g + ctx.green[level];
            b = b + ctx.blue[level];
        }
        ctx.red[level] = r;
        ctx.green[level] = g;
        ctx.blue[level] = b;
    }

    /**
     * One secondary ray along (dx, dy, dz) from the hit point, or, for a spread surface, the
     * average of a beam of rays aimed at a disk of radius {@code spread} at unit distance along
     * that direction, stratified over the disk; into slot {@code level}. A sample that would cross
     * to the wrong side of the surface is mirrored back across it (keeping its weight, so the
     * average neither gains nor loses energy).
     */
    private void beam(Hit hit, double dirX, double dirY, double dirZ, double spread, double kxr, double kxg,
                      double kxb, double kkr, double kkg, double kkb, int level, int budget, TraceContext ctx) {
        if (spread == 0) {
            secondary(hit, dirX, dirY, dirZ, kxr, kxg, kxb, kkr, kkg, kkb, level, budget, ctx);
            return;
        }
        double[] basis = ctx.vector;
        perpendicular(dirX, dirY, dirZ, basis);
        double ax = basis[0], ay = basis[1], az = basis[2];
        Vector.crossProduct(dirX, dirY, dirZ, ax, ay, az, basis);
        double bx = basis[0], by = basis[1], bz = basis[2];
        double nx = hit.normalX(), ny = hit.normalY(), nz = hit.normalZ();
        double side = nx * dirX + ny * dirY + nz * dirZ;
        SampleStream rnd = ctx.random;
        double offset = rnd.nextDouble();
        double sr = 0, sg = 0, sb = 0;
        double[] disk = ctx.disk;
        for (int i = 0; i < budget; ++i) {
            ctx.stopIfInterrupted(); // a beam may take millions of rays
            diskPoint(i, budget, offset, rnd, spread, disk);
            double cx = disk[0], cy = disk[1];
            double dx = dirX + cx * ax + cy * bx;
            double dy = dirY + cx * ay + cy * by;
            double dz = dirZ + cx * az + cy * bz;
            double dn = dx * nx + dy * ny + dz * nz;
            if (dn * side < 0) {
                dx -= 2 * dn * nx;
                dy -= 2 * dn * ny;
                dz -= 2 * dn * nz;
            }
            secondary(hit, dx, dy, dz, kxr, kxg, kxb, kkr, kkg, kkb, level, 1, ctx);
            sr += ctx.red[level];
            sg += ctx.green[level];
            sb += ctx.blue[level];
        }
        ctx.red[level] = sr / budget;
        ctx.green[level] = sg / budget;
        ctx.blue[level] = sb / budget;
    }

    /**
     * The colour seen along the secondary ray {@code new Ray(p, direction, n)} from the hit point,
     * scaled by kx, into slot {@code level}; its hit is shaded one level down with the
     * coefficient kk.
     */
    private void secondary(Hit hit, double dx, double dy, double dz, double kxr, double kxg, double kxb,
                           double kkr, double kkg, double kkb, int level, int budget, TraceContext ctx) {
        ctx.secondaryRays++;
        Hit next = ctx.hit(level - 1, Double.POSITIVE_INFINITY).setRay(hit.pointX(), hit.pointY(), hit.pointZ(),
                dx, dy, dz, hit.normalX(), hit.normalY(), hit.normalZ());
        double r, g, b;
        if (world.closestHit(next)) {
            calcColor(next, level - 1, kkr, kkg, kkb, budget, ctx);
            r = ctx.red[level - 1];
            g = ctx.green[level - 1];
            b = ctx.blue[level - 1];
        } else {
            Color bg = scene.background;
            r = bg.getR();
            g = bg.getG();
            b = bg.getB();
        }
        ctx.red[level] = r * kxr; // Color.scale(Double3)
        ctx.green[level] = g * kxg;
        ctx.blue[level] = b * kxb;
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

    /**
     * A unit vector orthogonal to (x, y, z), into {@code out}: the cross product with the x axis
     * (the y axis when v is near it), normalized.
     */
    private static void perpendicular(double x, double y, double z, double[] out) {
        Vector axis = Math.abs(x) < 0.9 ? Vector.AXIS_X : Vector.AXIS_Y;
        Vector.crossProduct(x, y, z, axis.getX(), axis.getY(), axis.getZ(), out);
        Vector.normalize(out[0], out[1], out[2], out);
    }

    private static double frac(double x) {
        return x - Math.floor(x);
    }
}
