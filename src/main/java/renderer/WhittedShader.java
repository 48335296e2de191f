package renderer;

import geometries.Geometry;
import geometries.Hit;
import geometries.Intersectable;
import geometries.LeanQueries;
import geometries.ShadowIndex;
import lighting.DirectionalLight;
import lighting.LightQueries;
import lighting.LightSource;
import lighting.PointLight;
import primitives.Color;
import primitives.Double3;
import primitives.Kernels;
import primitives.Material;
import primitives.Point;
import primitives.Rgb;
import primitives.Util;
import primitives.Vector;
import renderer.TraceContext.Bounce;
import renderer.TraceContext.Level;

/**
 * The shading of {@link RayTracerBasic}, over the geometry and lights one {@code prepare()} made:
 * immutable, shared by every worker; all per-ray state is in the worker's {@link TraceContext}.
 * Each recursion level shades into its own {@link Level}, whose colours are {@link Rgb} values
 * changed in place, so a ray allocates nothing for the library's geometries and lights.
 *
 * <p>Rays, points and normals are doubles (a ray lives in its level's {@link Hit}); colours and
 * per-channel coefficients are {@code Rgb}, whose kernels are {@code Color}'s and
 * {@code Double3}'s, so every sum and product has the bits of the same sum or product of those
 * objects. The golden-image tests and {@code DeterminismTest} hold the images to the bit.
 */
final class WhittedShader implements PreparedTracer {
    /** The recursion depth limit of reflection and refraction (the course's value). */
    static final int MAX_CALC_COLOR_LEVEL = 10;
    /** Below this accumulated coefficient (in every channel) a contribution is not traced (the course's value). */
    static final double MIN_CALC_COLOR_K = 0.001;
    /** Rays per glossy or diffuse-glass beam when none is set. */
    static final int DEFAULT_BEAM_SIZE = 16;
    /** Shadow rays toward a light with a radius when none is set. */
    static final int DEFAULT_SHADOW_SAMPLES = 16;

    /**
     * @param rays rays per glossy or diffuse-glass beam
     * @return {@code rays}
     * @throws IllegalArgumentException when it is below 1, naming it
     */
    static int requireBeamSize(int rays) {
        if (rays < 1) throw new IllegalArgumentException("beam size must be at least 1 ray, got " + rays);
        return rays;
    }

    /**
     * @param samples shadow rays toward a light with a radius
     * @return {@code samples}
     * @throws IllegalArgumentException when it is below 1, naming it
     */
    static int requireShadowSamples(int samples) {
        if (samples < 1) throw new IllegalArgumentException("shadow samples must be at least 1, got " + samples);
        return samples;
    }

    /** The golden-ratio conjugate: spreads beam samples evenly in angle (a Fibonacci lattice). */
    private static final double PHI = 0.6180339887498949;

    /**
     * The scene's background and ambient intensity as prepared: a render fails when the scene
     * replaces either during it, and a direct trace after a replacement prepares again
     * ({@link SceneStamp}).
     */
    private final Color background, ambient;
    /** The scene's geometry as the render queries it: a BVH or the flat list. */
    private final Intersectable world;
    private final LightSource[] lights;
    /** Per light, its light buffer, or null (a soft or a user's light, a world the index does not take). */
    private final ShadowIndex[] shadowIndexes;
    /** Rays of the first glossy or diffuse-glass beam on a camera ray's path (each bounce below it traces one). */
    private final int beamSize;
    /** Shadow rays toward a light with a radius. */
    private final int shadowSamples;

    WhittedShader(Color background, Color ambient, Intersectable world, LightSource[] lights, int beamSize,
                  int shadowSamples) {
        this.background = background;
        this.ambient = ambient;
        this.world = world;
        this.lights = lights;
        this.shadowIndexes = shadowIndexes(world, lights);
        this.beamSize = beamSize;
        this.shadowSamples = shadowSamples;
    }

    /**
     * The light buffer of each library light whose shadow ray is one ray (a point, spot or
     * directional light of radius 0), over {@code world}. The index answers for a ray's geometry
     * only, checking that the ray ends at the light or runs along it, so a light it was built for
     * wrongly would only get no help from it.
     */
    private static ShadowIndex[] shadowIndexes(Intersectable world, LightSource[] lights) {
        ShadowIndex[] indexes = new ShadowIndex[lights.length];
        double[] l = new double[3];
        for (int i = 0; i < lights.length; ++i) {
            LightSource light = lights[i];
            if (!LightQueries.isLibraryLight(light) || light.getRadius() != 0) continue;
            if (light instanceof DirectionalLight) {
                // The shadow rays' direction as Hit.secondary makes it: -l, normalized.
                LightQueries.getL(light, 0, 0, 0, l);
                Kernels.normalize(-l[0], -l[1], -l[2], l);
                indexes[i] = LeanQueries.shadowIndexAlong(world, l[0], l[1], l[2]);
            } else if (light instanceof PointLight) {
                Point p = light.getPosition();
                indexes[i] = LeanQueries.shadowIndexFrom(world, p.getX(), p.getY(), p.getZ());
            }
        }
        return indexes;
    }

    /** @return light {@code light}'s buffer, or null (for the tests) */
    ShadowIndex shadowIndex(int light) {
        return shadowIndexes[light];
    }

    /** The scene's tree may take its vector walk from the first ray ({@link LeanQueries#expectCameraRays}). */
    @Override
    public void expectCameraRays(long cameraRays) {
        LeanQueries.expectCameraRays(world, cameraRays);
    }

    /** @return the words of the walk the scene's tree takes now ({@link LeanQueries#walkDescription}) */
    String walk() {
        return LeanQueries.walkDescription(world);
    }

    /** The scene's tree warms its vector walk ({@link LeanQueries#expectLongWalk}). */
    @Override
    public void expectLongRender() {
        LeanQueries.expectLongWalk(world);
    }

    /**
     * The colour seen along the camera ray in {@link TraceContext#cameraRay()}: the colour at its
     * closest hit plus the ambient light times the material's kA, or the background.
     *
     * @return the context's {@link TraceContext#cameraColour()}, valid until its next trace
     */
    @Override
    public Rgb traceRay(TraceContext ctx) {
        ctx.stopIfInterrupted(); // a pixel may take 65,536 camera samples
        ctx.requireWithinBudget(0); // the camera ray is counted already
        Level top = ctx.top();
        Hit hit = top.hit.reset(Double.POSITIVE_INFINITY);
        if (!LeanQueries.closestHit(world, hit)) return top.colour.set(background);
        Double3 kA = hit.getGeometry().getMaterial().kA; // ambient = I_A·kA(light)·kA(material)
        top.weight.set(1, 1, 1);
        calcColor(top, beamSize, ctx);
        return top.colour.addProduct(ambient, kA);
    }

    /**
     * The colour at the hit of {@code at}'s record (found by a closest-hit query of its ray):
     * emission, plus the local effects when the ray meets the surface at an angle, plus the
     * indirect light above level 1; into and returned as {@code at.colour}.
     *
     * @param budget rays a glossy beam below this point may use (see {@link RayTracerBasic#setBeamSize(int)})
     */
    private Rgb calcColor(Level at, int budget, TraceContext ctx) {
        Hit hit = at.hit;
        Geometry geometry = hit.getGeometry();
        hit.computeSurface();
        double nv = Util.alignZero(hit.normalX() * hit.directionX() + hit.normalY() * hit.directionY()
                + hit.normalZ() * hit.directionZ());
        Material material = geometry.getMaterial();
        Rgb colour = at.colour.set(geometry.getEmission());
        if (nv != 0) colour.add(calcLocalEffects(hit, nv, material, at.weight, ctx));
        if (at.level != 1) colour.add(calcGlobalEffects(at, nv, material, budget, ctx));
        return colour;
    }

    /**
     * Emission aside, the light arriving directly: Phong per light, times its shadow
     * transparency; into and returned as {@code ctx.local}. A light whose transparency times the
     * path's {@code weight} is below {@link #MIN_CALC_COLOR_K} in every channel adds
     * nothing.
     */
    private Rgb calcLocalEffects(Hit hit, double nv, Material material, Rgb weight, TraceContext ctx) {
        Rgb local = ctx.local.setZero();
        Double3 kD = material.kD, kS = material.kS;
        double px = hit.pointX(), py = hit.pointY(), pz = hit.pointZ();
        double nx = hit.normalX(), ny = hit.normalY(), nz = hit.normalZ();
        double vx = hit.directionX(), vy = hit.directionY(), vz = hit.directionZ();
        double[] l = ctx.light, out = ctx.lightIntensity;
        Rgb intensity = ctx.intensity, phong = ctx.phong;
        LightSource[] lights = this.lights;
        // A material without a specular term (kS = 0, most of them) skips Math.pow, the dearest
        // step of the loop: kS·spec is a zero of kS's sign for every finite spec ≥ 0, spec = 0
        // included, so the sum is the same to the bit. Only an infinite power differed, which
        // takes a user's getNormal that returns a vector far from unit length: 0·∞ made the term
        // NaN. 5 % of the 16-spp render of the 137-primitive Sunflow scene (BENCHMARKS.md).
        boolean specular = !kS.isZero();
        for (int li = 0; li < lights.length; ++li) {
            LightSource light = lights[li];
            LightQueries.getL(light, px, py, pz, l);
            double lx = l[0], ly = l[1], lz = l[2];
            double nl = Util.alignZero(nx * lx + ny * ly + nz * lz);
            if (nl * nv <= 0) continue; // the light is on the other side of the surface from the viewer
            // Phong: kD·|n·l| + kS·max(0, −r·v)^shininess, with r = l − 2(n·l)n.
            double rx = lx - 2 * nl * nx, ry = ly - 2 * nl * ny, rz = lz - 2 * nl * nz;
            double minusVR = -Util.alignZero(rx * vx + ry * vy + rz * vz);
            double spec = minusVR <= 0 || !specular ? 0 : Math.pow(minusVR, material.nShininess);
            double absNl = Math.abs(nl);
            LightQueries.getIntensity(light, px, py, pz, out);
            intensity.set(out[0], out[1], out[2]);
            phong.setScaled(kD, absNl).addScaled(kS, spec);
            // Nothing to shadow (a spot light turned away, a material with kD = kS = 0): the term
            // is exactly zero whatever the occluders, so the shadow walk is not traced.
            if (intensity.productIsZero(phong)) continue;
            Rgb transparency = transparency(hit, light, li, ctx);
            if (transparency.productLowerThan(weight, MIN_CALC_COLOR_K)) continue;
            local.addProduct(intensity, transparency, phong);
        }
        return local;
    }

    /**
     * The product of kT of the occluders between the hit point and light {@code li} (whose unit
     * direction toward the point is in {@code ctx.light}): the course's hard shadow for a point
     * light, or the average over {@link #shadowSamples} points of its disk.
     *
     * @return the transparency, per channel: the walk's own value or {@code ctx.transparency},
     *         valid until the next shadow ray
     */
    private Rgb transparency(Hit hit, LightSource light, int li, TraceContext ctx) {
        double radius = light.getRadius();
        Intersectable w = world;
        Transmittance walk = ctx.transmittance;
        ShadowCache cache = ctx.shadowCache;
        double[] l = ctx.light;
        double lx = l[0], ly = l[1], lz = l[2];
        double px = hit.pointX(), py = hit.pointY(), pz = hit.pointZ();
        double nx = hit.normalX(), ny = hit.normalY(), nz = hit.normalZ();
        if (radius == 0) {
            ctx.requireWithinBudget(1); // thousands of lights at each of a thousand shaded points
            ctx.shadowRays++;
            cache.trace(w, ctx.shadow.secondary(px, py, pz, -lx, -ly, -lz, nx, ny, nz), LightQueries.getDistance(light, px, py, pz), li,
                    shadowIndexes[li], walk);
            return walk.product;
        }
        // Soft shadow: stratified points on the disk of the light facing p.
        Point c = light.getPosition();
        double tx = -lx, ty = -ly, tz = -lz; // toward the light
        double[] basis = ctx.vector;
        perpendicular(tx, ty, tz, basis);
        double ax = basis[0], ay = basis[1], az = basis[2];
        Kernels.crossProduct(tx, ty, tz, ax, ay, az, basis);
        double bx = basis[0], by = basis[1], bz = basis[2];
        double side = nx * tx + ny * ty + nz * tz;
        Rgb sum = ctx.transparency.setZero();
        double offset = ctx.random.nextDouble();
        double[] disk = ctx.disk;
        for (int i = 0; i < shadowSamples; ++i) {
            ctx.stopIfInterrupted(); // a soft shadow may take millions of rays
            ctx.requireWithinBudget(1);
            diskPoint(i, shadowSamples, offset, radius, ctx);
            double sx = c.getX() + disk[0] * ax + disk[1] * bx;
            double sy = c.getY() + disk[0] * ay + disk[1] * by;
            double sz = c.getZ() + disk[0] * az + disk[1] * bz;
            double dx = sx - px, dy = sy - py, dz = sz - pz;
            double dist = Math.sqrt(dx * dx + dy * dy + dz * dz);
            // A point of the disk below the surface's horizon sends no light to p.
            if (dist == 0 || (dx * nx + dy * ny + dz * nz) * side <= 0) continue;
            ctx.shadowRays++;
            cache.trace(w, ctx.shadow.secondary(px, py, pz, dx, dy, dz, nx, ny, nz), dist, li, null, walk); // no index: the rays end across a disk
            sum.add(walk.product);
        }
        return sum.reduce(shadowSamples);
    }

    /**
     * Reflection and transmission at {@code at}'s hit: the sum of its two bounces, into and
     * returned as {@code at.indirect}. A material with an index of refraction ({@link Material#ior}
     * ≠ 1) that transmits splits its light between them first ({@link #refract}); any other
     * reflects along the mirror direction and transmits along the ray's own.
     */
    private Rgb calcGlobalEffects(Level at, double nv, Material material, int budget, TraceContext ctx) {
        Rgb indirect = at.indirect.setZero();
        Hit hit = at.hit;
        Bounce reflection = at.reflection, transmission = at.transmission;
        if (material.ior != 1 && !material.kT.isZero()) {
            refract(hit, nv, material, reflection, transmission);
        } else {
            if (material.kR.isZero() && material.kT.isZero()) return indirect; // most materials: no bounce
            reflection.k.set(material.kR);
            transmission.k.set(material.kT);
            transmission.aim(hit.directionX(), hit.directionY(), hit.directionZ(), material.transmissionSpread);
        }
        // The mirror direction r = v − 2(v·n)n of the hit's ray.
        double vx = hit.directionX(), vy = hit.directionY(), vz = hit.directionZ();
        if (nv != 0) {
            vx = vx - 2 * nv * hit.normalX();
            vy = vy - 2 * nv * hit.normalY();
            vz = vz - 2 * nv * hit.normalZ();
        }
        reflection.aim(vx, vy, vz, material.reflectionSpread);
        addBounce(at, reflection, budget, ctx);
        addBounce(at, transmission, budget, ctx);
        return indirect;
    }

    /**
     * The two bounces of a refracting material ({@link Material#ior} ≠ 1). Inside and outside are
     * told by the normal: a ray against the normal ({@code v·n < 0}) enters the material (from
     * index 1 to {@code ior}), a ray along it leaves (from {@code ior} to 1); there is no stack of
     * media, so a refracting body sits in air and is closed, its normals pointing out. The
     * transmitted ray follows Snell's law; beyond the critical angle it is reflected instead (total
     * internal reflection, with weight kT, and the transmission's k is zero); when the material
     * reflects (kR &gt; 0) the Fresnel reflectance F (Schlick's approximation, with the cosine on
     * the side of the lower index) moves F·kT from the transmission to the reflection. Sets both
     * bounces' k and the transmission's direction and spread.
     */
    private static void refract(Hit hit, double nv, Material material, Bounce reflection, Bounce transmission) {
        double eta = nv < 0 ? 1 / material.ior : material.ior; // n₁ / n₂
        double cosI = Math.abs(nv);
        double cos2T = 1 - eta * eta * (1 - cosI * cosI);
        Rgb kR = reflection.k.set(material.kR), kT = transmission.k.set(material.kT);
        if (cos2T <= 0) { // total internal reflection: all the transmitted light is reflected
            kR.add(kT);
            kT.setZero();
            return;
        }
        double cosT = Math.sqrt(cos2T);
        // t = η·v + (η·cosI − cosT)·n', with n' the normal on the incoming side (−sign(v·n)·n).
        double a = (eta * cosI - cosT) * (nv < 0 ? 1 : -1);
        transmission.aim(eta * hit.directionX() + a * hit.normalX(), eta * hit.directionY() + a * hit.normalY(),
                eta * hit.directionZ() + a * hit.normalZ(), material.transmissionSpread);
        if (!kR.isZero()) {
            double r0 = (material.ior - 1) / (material.ior + 1);
            r0 *= r0;
            double c = 1 - (eta <= 1 ? cosI : cosT);
            double f = r0 + (1 - r0) * c * c * c * c * c;
            kR.addScaled(kT, f);
            kT.scale(1 - f);
        }
    }

    /**
     * Adds the light of one bounce to {@code at.indirect}: nothing when its k is zero, or when the
     * path weight below it ({@code at.weight · k}) is under {@link #MIN_CALC_COLOR_K}
     * in every channel.
     */
    private void addBounce(Level at, Bounce bounce, int budget, TraceContext ctx) {
        if (bounce.k.isZero()) return;
        if (at.below.weight.setProduct(at.weight, bounce.k).lowerThan(MIN_CALC_COLOR_K)) return;
        at.indirect.add(beam(at, bounce, budget, ctx));
    }

    /**
     * The light a bounce brings back to the hit, times its k, into and returned as
     * {@code at.beam}: the colour seen along one secondary ray in the bounce's direction, or, for a
     * spread bounce, the average over a beam of {@code budget} rays aimed at a disk of radius
     * {@code spread} at unit distance along that direction, stratified over the disk. A sample that
     * would cross to the wrong side of the surface is mirrored back across it (keeping its weight,
     * so the average neither gains nor loses energy). Below a beam, each bounce traces one ray.
     */
    private Rgb beam(Level at, Bounce bounce, int budget, TraceContext ctx) {
        Hit hit = at.hit;
        Level below = at.below;
        Rgb k = bounce.k;
        double dirX = bounce.dirX, dirY = bounce.dirY, dirZ = bounce.dirZ;
        if (bounce.spread == 0) {
            below.secondaryRay(hit, dirX, dirY, dirZ);
            return at.beam.setProduct(shadeSecondaryRay(below, budget, ctx), k);
        }
        double[] basis = ctx.vector;
        perpendicular(dirX, dirY, dirZ, basis);
        double ax = basis[0], ay = basis[1], az = basis[2];
        Kernels.crossProduct(dirX, dirY, dirZ, ax, ay, az, basis);
        double bx = basis[0], by = basis[1], bz = basis[2];
        double nx = hit.normalX(), ny = hit.normalY(), nz = hit.normalZ();
        double side = nx * dirX + ny * dirY + nz * dirZ;
        double offset = ctx.random.nextDouble();
        Rgb sum = at.beam.setZero();
        double[] disk = ctx.disk;
        for (int i = 0; i < budget; ++i) {
            ctx.stopIfInterrupted(); // a beam may take millions of rays
            diskPoint(i, budget, offset, bounce.spread, ctx);
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
            below.secondaryRay(hit, dx, dy, dz);
            sum.addProduct(shadeSecondaryRay(below, 1, ctx), k);
        }
        return sum.reduce(budget);
    }

    /**
     * The colour seen along the secondary ray in {@code at}'s record: the colour at its closest
     * hit, shaded at that level, or the background; into and returned as {@code at.colour}.
     */
    private Rgb shadeSecondaryRay(Level at, int budget, TraceContext ctx) {
        ctx.requireWithinBudget(1); // a path that reflects and transmits at every level doubles at each
        ctx.secondaryRays++;
        if (LeanQueries.closestHit(world, at.hit)) return calcColor(at, budget, ctx);
        return at.colour.set(background);
    }

    /**
     * Point {@code i} of {@code n} stratified over a disk of {@code radius}: stratified in area
     * (radius² uniform within stratum i) and spread in angle by the golden ratio from a random
     * {@code offset}, so any n points cover the disk evenly. Writes the two in-plane coordinates
     * into {@code ctx.disk}; draws one number from {@code ctx.random}.
     */
    private static void diskPoint(int i, int n, double offset, double radius, TraceContext ctx) {
        double rad = radius * Math.sqrt((i + ctx.random.nextDouble()) / n);
        double ang = 2 * Math.PI * frac(offset + i * PHI);
        double[] out = ctx.disk;
        out[0] = rad * Math.cos(ang);
        out[1] = rad * Math.sin(ang);
    }

    /**
     * A unit vector orthogonal to (x, y, z), into {@code out}: the cross product with the x axis
     * (the y axis when v is near it), normalized.
     */
    private static void perpendicular(double x, double y, double z, double[] out) {
        Vector axis = Math.abs(x) < 0.9 ? Vector.AXIS_X : Vector.AXIS_Y;
        Kernels.crossProduct(x, y, z, axis.getX(), axis.getY(), axis.getZ(), out);
        Kernels.normalize(out[0], out[1], out[2], out);
    }

    private static double frac(double x) {
        return x - Math.floor(x);
    }
}
