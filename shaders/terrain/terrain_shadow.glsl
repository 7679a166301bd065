// Terrain shadows (issue 13): the share of the sun's disc that the terrain leaves visible
// from a point on the ground, by a march over the height field towards the sun.
//
// Include after terrain/height.glsl. Written in the subset of GLSL that is also C++, as
// height.glsl (see noise/simplex.glsl for the rules): terrain/terrain_shadow.cpp includes
// the very same text, so tests/test_terrain_shadow.cpp checks what the GPU runs.
//
// Why a march over the height function rather than a shadow map: the height field is
// analytic and the same text on the CPU and the GPU, so the shadow needs no pass and no
// memory of its own, is testable against a CPU march, and has no resolution to choose: a
// shadow map would need cascades to serve a camera 2 m above a valley and one in orbit
// (the projected grid has no fixed extent), an extra pass drawing the terrain from the sun,
// and its texels would swim and alias at a low sun, exactly when the shadows are long. The
// march's cost is bounded by its sample count (TERRAIN_SHADOW_SAMPLES) and paid only for
// lit pixels at a sun low enough for the terrain to rise into its ray.
//
// The march, from the ground at the point's direction (the analytic height, not the mesh's,
// which is off by up to a triangle's sag) along the ray to the sun, samples at distances
// growing geometrically from TERRAIN_SHADOW_FIRST_KM to TERRAIN_SHADOW_MAX_KM (the near
// terrain decides small shadows, the far only large ones); at each sample the clearance
// angle (height of the ray above the terrain / distance: the terrain's elevation below the
// ray as seen from the point). The smallest clearance is where the horizon line stands
// relative to the sun's centre, and the share of the disc above that line is the
// visibility: a penumbra as wide as the sun (Quilez's soft shadows, "free penumbra", with the
// disc's true angular radius instead of a softness constant). It stops early once the ray
// has risen above shape.maxHeight (nothing further can reach it: at a high sun after a few
// km, which is the tangent-plane bound taken sample by sample) or the whole disc is hidden.
// Samples far apart cannot see features finer than their spacing, so they take fewer
// mountain octaves (terrainShadowOctaves): most of the cost is in the near samples. And a
// sample takes its octaves coarse to fine only until they show that the terrain there cannot
// come closer to the ray than the clearance found so far (terrainShadowHeightBelow): a ray a
// kilometre above a meadow is clear of it after one or two of the eight (at the `ground` view,
// 1280x720 on llvmpipe, the shadow's passes went from 138 to 58 ms), and the clearance is
// exact only below the sun's radius plus TERRAIN_SHADOW_EXACT_MARGIN, all that is read of it.
//
// Units: points in km from the planet centre (the atmosphere's), heights in m above sea
// level (height.glsl's).

// The longest shadow marched, km. A 5 km peak at a 5 deg sun throws 57 km of shadow, at 3
// deg 95 km; the default field's bound (maxHeight 8 km) at 5 deg about 90 km. Below ~4 deg the
// sun is already dim and red through the air (transmittance), and the planet's curvature
// lifts the ray by t^2 / 2R (0.8 km at 100 km). 100 km covers the default Earth's relief
// down to a sun about 4.5 deg high.
const float TERRAIN_SHADOW_MAX_KM = 100.0f;
// The first sample, km: closer ground is the surface's own slope, which the normal's
// cos(sun) already shades; and the height field's float precision (a metre or so at the
// finest octave) would make clearances at a few metres noise.
const float TERRAIN_SHADOW_FIRST_KM = 0.05f;
// Samples from the first to the longest, geometrically spaced: each 1.35 x the last (35 %
// gaps), the most any pixel pays. A ridge narrower than the gap at its distance can slip
// between two samples; the far samples' coarse octaves make ridges there wide.
const int TERRAIN_SHADOW_SAMPLES = 26;
// Height field noise allowance, m: clearances are measured from this far above the terrain
// so that rounding (float directions on a 6000 km sphere resolve about 0.4 m) does not
// shadow a lit slope; 1 m at the first sample is 0.02 rad, less than a degree.
const float TERRAIN_SHADOW_BIAS_M = 1.0f;
// Fewer octaves for a sample: it keeps the octaves whose lattice cells are at least this
// share of the gap to the next sample (or of the pixel's footprint).
const float TERRAIN_SHADOW_OCTAVE_CELLS = 0.5f;
// The clearance is exact up to the sun's angular radius plus this (rad), and beyond it only known
// to be beyond: render/terrain_shadow_samples.glsl's TERRAIN_SHADOW_LIT_MARGIN, the most beyond the
// radius that a clearance is read, stays below it.
const float TERRAIN_SHADOW_EXACT_MARGIN = 0.05f;
const float TERRAIN_SHADOW_PI = 3.14159265f;

// The share of a uniform disc of angular radius `sunAngularRadius` that lies above a
// straight horizon `clearance` radians below its centre (negative: above it): the
// circular segment's area, 1 - (acos(u) - u sqrt(1 - u^2)) / pi for u = clearance / radius.
float terrainShadowDiscShare(float clearance, float sunAngularRadius) {
    float u = clamp(clearance / sunAngularRadius, -1.0f, 1.0f);
    return 1.0f - (acos(u) - u * sqrt(1.0f - u * u)) / TERRAIN_SHADOW_PI;
}

// Mountain octaves a sample needs when features finer than `featureKm` cannot matter: the
// octaves whose lattice cells (R / (frequency 2^i)) are at least TERRAIN_SHADOW_OCTAVE_CELLS
// x featureKm, at least one; all of them for featureKm 0.
int terrainShadowOctaves(TerrainShape shape, float planetRadiusKm, float featureKm) {
    if (shape.mountainOctaves <= 1 || featureKm <= 0.0f) return shape.mountainOctaves;
    float coarsestCellKm = planetRadiusKm / shape.mountainFrequency;
    float halvings = log2(max(coarsestCellKm / (TERRAIN_SHADOW_OCTAVE_CELLS * featureKm), 1.0f));
    return clamp(int(halvings) + 1, 1, shape.mountainOctaves);
}

// The most one octave of the mountains adds (terrainMountainOctave's value, at most 1 for simplex
// noise in [-1, 1], which tests/test_noise.cpp holds it to; a twentieth more).
const float TERRAIN_SHADOW_OCTAVE_MAX = 1.05f;

// The terrain's height (m) at `direction` with `octaves` mountain octaves (terrainHeight's field with
// that count), where it may rise above `ceilingM`; where it cannot, a bound on it instead, at most
// about ceilingM: the octaves are summed coarse to fine, and once the sum so far plus the most the
// rest can add (TERRAIN_SHADOW_OCTAVE_MAX x their amplitudes) keeps the height at or below the
// ceiling, the rest are not evaluated and the height at that sum is returned. The land's height is
// lowland + scale x noise^2 (terrainHeightFromParts without a footprint), rising with the noise. A
// march sample kilometres above a meadow sees that after one or two octaves: the fine octaves, most
// of the cost, only where the ray passes close to the ground. `boundOctaves` false: every octave.
float terrainShadowHeightBelow(vec3 direction, TerrainShape shape, samplerCube continents, int octaves,
                               float ceilingM, bool boundOctaves) {
    float e = continentValue(direction, continents);
    int count = e >= 0.0f ? clamp(octaves, 0, 10) : 0;  // the sea floor takes no octave (terrainHeight)
    // The noise at which the land's height reaches the ceiling.
    float lowland;
    float scale;
    terrainLandParts(shape, e, lowland, scale);
    float room = ceilingM - lowland;
    float noiseCeiling = scale > 0.0f ? sqrt(max(room, 0.0f) / scale) : (room >= 0.0f ? 1.0e30f : 0.0f);
    if (!boundOctaves) noiseCeiling = -1.0f;
    // The octaves' amplitudes 1, 1/2, 1/4, ... sum to 2 - 2^(1 - count) (exactly, in float).
    float total = 2.0f - ldexp(2.0f, -count);
    float remaining = total;
    float ceilingSum = noiseCeiling * total;
    vec3 p = direction * shape.mountainFrequency + terrainXyz(shape.mountainOffset);
    float sum = 0.0f;
    float amplitude = 1.0f;
    float frequency = 1.0f;
    int k = 0;
    // A loop, not an if per octave: a software renderer leaves it once no pixel of a group needs
    // the next octave (README "Programs, not branches").
    for (; k < count && sum + TERRAIN_SHADOW_OCTAVE_MAX * remaining > ceilingSum; k++) {
        float slope;
        sum += amplitude * terrainMountainOctave(simplexNoise(p * frequency), shape.ridgedWeight, slope);
        remaining -= amplitude;
        frequency *= 2.0f;
        amplitude *= 0.5f;
    }
    float noise = count > 0 ? (k < count ? sum + TERRAIN_SHADOW_OCTAVE_MAX * remaining : sum) / total : 0.0f;
    vec3 gradient;
    float heightVariance;
    float gradientVariance;
    return terrainHeightFromParts(shape, e, vec3(0.0f), noise, vec3(0.0f), 0.0f, 0.0f, gradient, heightVariance,
                                  gradientVariance);
}

// Visibility of the sun from the ground at `point` (km from the planet centre; only its
// direction is used: the march starts on the analytic surface), in [0, 1]: 1 lit, 0 in the
// terrain's shadow, between in the penumbra. `sun` is the unit direction to the sun,
// `footprintKm` the pixel's size on the ground (0: a point): shadows of features smaller
// than it are not resolved, and when the longest shadow the terrain can throw at this sun is
// shorter than it, nothing is marched. `samples` is TERRAIN_SHADOW_SAMPLES, or 0 for no
// march (visibility 1). A parameter rather than the constant, and from a uniform on the GPU:
// a constant trip count lets the compiler unroll the march, 26 inlined height fields with
// their octaves, which took llvmpipe minutes to compile; and a software renderer skips a
// loop of 0 iterations, where it would run the march in a branch not taken.
// `startM`: the march starts that many metres above sea level where the ground is lower (the
// sea's surface over the sea floor); terrainSunVisibility below starts on the ground.
// terrainShadowClearanceAbove: the march's smallest clearance angle (rad; 1 where nothing was
// marched): the disc is whole at sunAngularRadius and above, gone at -sunAngularRadius and below
// (where the march stops, so a clearance that low says "hidden", not by how much); above
// sunAngularRadius + TERRAIN_SHADOW_EXACT_MARGIN it says only "above that".
// terrainShadowClearanceMarch: the same with the octaves' bounds (terrainShadowHeightBelow) taken
// where the terrain cannot come within `exactBelow` rad of the ray, or not (`boundOctaves` false):
// the clearance is the same below exactBelow, and at or above it above.
float terrainShadowClearanceMarch(vec3 point, float startM, vec3 sun, float planetRadiusKm, float sunAngularRadius,
                                  float footprintKm, int samples, TerrainShape shape, samplerCube continents,
                                  float exactBelow, bool boundOctaves) {
    vec3 up = normalize(point);
    float sinElevation = dot(up, sun);
    float groundM = max(terrainHeight(up, shape, continents), startM);
    float reliefKm = (shape.maxHeight - groundM) * 0.001f;  // how far the terrain can rise above the point
    if (reliefKm <= 0.0f) return 1.0f;
    // Tangent-plane bound: the ray is above maxHeight after reliefKm / sin(elevation), sooner
    // on the sphere; a shadow shorter than the pixel is not marched.
    float first = max(TERRAIN_SHADOW_FIRST_KM, footprintKm);
    if (sinElevation > 0.0f && reliefKm < first * sinElevation) return 1.0f;
    float startKm = planetRadiusKm + groundM * 0.001f;
    float growth = pow(TERRAIN_SHADOW_MAX_KM / TERRAIN_SHADOW_FIRST_KM, 1.0f / float(TERRAIN_SHADOW_SAMPLES - 1));
    float clearance = 1.0f;  // rad: the smallest so far; 1 is far above any sun's radius
    float t = first;
    for (int i = 0; i < min(samples, TERRAIN_SHADOW_SAMPLES); i++) {
        if (t > TERRAIN_SHADOW_MAX_KM) break;
        // The ray's rise above the start radius, |s + t sun| - s = t (2 s sin + t) / (|..| + s):
        // nothing of planet size is subtracted.
        float radius = sqrt(startKm * startKm + t * (2.0f * startKm * sinElevation + t));
        float riseM = 1000.0f * t * (2.0f * startKm * sinElevation + t) / (radius + startKm);
        float rayM = groundM + riseM;
        if (rayM > shape.maxHeight) break;  // above all the terrain can reach, now and further on
        vec3 direction = normalize(up * startKm + sun * t);
        float gapKm = t * (growth - 1.0f);
        // The terrain matters here only where it comes closer to the ray than the clearance so far
        // (or than exactness needs): below that ceiling, its height's bound will do.
        float ceilingM = rayM + TERRAIN_SHADOW_BIAS_M - min(clearance, exactBelow) * t * 1000.0f;
        int octaves = terrainShadowOctaves(shape, planetRadiusKm, max(gapKm, footprintKm));
        float terrainM = terrainShadowHeightBelow(direction, shape, continents, octaves, ceilingM, boundOctaves);
        clearance = min(clearance, (rayM + TERRAIN_SHADOW_BIAS_M - terrainM) * 0.001f / t);
        if (clearance <= -sunAngularRadius) break;  // the whole disc is hidden
        t *= growth;
    }
    return clearance;
}
float terrainShadowClearanceAbove(vec3 point, float startM, vec3 sun, float planetRadiusKm, float sunAngularRadius,
                                  float footprintKm, int samples, TerrainShape shape, samplerCube continents) {
    return terrainShadowClearanceMarch(point, startM, sun, planetRadiusKm, sunAngularRadius, footprintKm, samples,
                                       shape, continents, sunAngularRadius + TERRAIN_SHADOW_EXACT_MARGIN, true);
}
float terrainSunVisibilityAbove(vec3 point, float startM, vec3 sun, float planetRadiusKm, float sunAngularRadius,
                                float footprintKm, int samples, TerrainShape shape, samplerCube continents) {
    return terrainShadowDiscShare(terrainShadowClearanceAbove(point, startM, sun, planetRadiusKm, sunAngularRadius,
                                                              footprintKm, samples, shape, continents),
                                  sunAngularRadius);
}

// The ground's own visibility: the march starts on the analytic surface under `point`.
float terrainSunVisibility(vec3 point, vec3 sun, float planetRadiusKm, float sunAngularRadius, float footprintKm,
                           int samples, TerrainShape shape, samplerCube continents) {
    return terrainSunVisibilityAbove(point, -1.0e9f, sun, planetRadiusKm, sunAngularRadius, footprintKm, samples,
                                     shape, continents);
}

// How far a ray from `startM` above sea level, rising with sine sinRise, can still meet terrain
// no higher than `topM`, km: beyond it the ray stands above that height (the sphere falls away
// below it by t^2 / 2R too). Solves t sinRise + t^2 / 2R = climb in its cancellation-free form.
float terrainReachBelowHeightKm(float topM, float startM, float sinRise, float planetRadiusKm) {
    float climbKm = max(topM - startM, 0.0f) * 0.001f;
    float s = max(sinRise, 0.0f);
    return 2.0f * climbKm / (sqrt(s * s + 2.0f * climbKm / planetRadiusKm) + s);
}

// Turns of terrainReachBelowLandKm's tightening.
const int TERRAIN_REACH_TIGHTENINGS = 3;

// How far, at most `limitKm`, a ray from the surface point at `up`, `startM` above sea level,
// rising with sine sinRise, can still meet the terrain near it, km (0: it cannot): within a reach
// r the continent value is at most e(up) + L (1.25 r / R + slack) (the map's slope bound
// `continentLipschitz` per radian, src/ocean/land_cull.h, over the reach x 1.25 for the ray's
// curve over the sphere, plus `sampleSlackRad`, the filter's rounding of a sample's place), and
// the terrain no higher than terrainHeightBound there. Each turn takes the reach below the bound
// over the last reach, starting from the highest mountain's (or the limit): every turn's reach r
// is one beyond which, up to the first, the ray stays above the bound (the bound over (r, r0]
// is at most its value at r0, which the ray clears past the new reach). From orbit a coast's
// rays clear its lowlands in a few kilometres, where the highest mountain's reach was tens.
// No slope bound (0): the highest mountain's reach.
// Two rays from the same point at once (x and y: the sea's light takes its reflected ray's and the
// sun's), with one continent value and one loop: a software renderer runs a loop's first turn
// for every group of pixels, and the two loops apart were twice that (orbit, 1280x720: the sea's
// light 3-4 ms). A reach at 0 stays 0 through the turns the other takes (each turn's reach is at
// most the last), so each is what it would be alone.
// `e`: the continent value at `up` (continentValue), where the caller has it already.
vec2 terrainReachesBelowLandKmAt(float e, float startM, vec2 sinRise, vec2 limitKm, float planetRadiusKm,
                                 float continentLipschitz, float sampleSlackRad, TerrainShape shape) {
    vec2 reach = vec2(min(terrainReachBelowHeightKm(shape.maxHeight, startM, sinRise.x, planetRadiusKm), limitKm.x),
                      min(terrainReachBelowHeightKm(shape.maxHeight, startM, sinRise.y, planetRadiusKm), limitKm.y));
    if (!(continentLipschitz > 0.0f)) return reach;
    // Until the reaches are 0 (no land near enough to rise into the rays): the open sea leaves
    // after the first turn, and a group of pixels all at open sea with it (a software renderer
    // runs a loop's turns while any pixel of the group is still in it; every turn here ran per
    // sea pixel).
    for (int i = 0; i < TERRAIN_REACH_TIGHTENINGS && (reach.x > 0.0f || reach.y > 0.0f); i++) {
        vec2 eMax = e + continentLipschitz * (1.25f * reach / planetRadiusKm + sampleSlackRad);
        reach.x = min(reach.x, terrainReachBelowHeightKm(terrainHeightBound(shape, eMax.x), startM, sinRise.x,
                                                         planetRadiusKm));
        reach.y = min(reach.y, terrainReachBelowHeightKm(terrainHeightBound(shape, eMax.y), startM, sinRise.y,
                                                         planetRadiusKm));
    }
    return reach;
}
vec2 terrainReachesBelowLandKm(vec3 up, float startM, vec2 sinRise, vec2 limitKm, float planetRadiusKm,
                               float continentLipschitz, float sampleSlackRad, TerrainShape shape,
                               samplerCube continents) {
    float e = continentValue(up, continents);
    return terrainReachesBelowLandKmAt(e, startM, sinRise, limitKm, planetRadiusKm, continentLipschitz,
                                       sampleSlackRad, shape);
}
float terrainReachBelowLandKm(vec3 up, float startM, float sinRise, float limitKm, float planetRadiusKm,
                              float continentLipschitz, float sampleSlackRad, TerrainShape shape,
                              samplerCube continents) {
    return terrainReachesBelowLandKm(up, startM, vec2(sinRise), vec2(limitKm), planetRadiusKm, continentLipschitz,
                                     sampleSlackRad, shape, continents)
        .x;
}

// Whether the terrain may shadow the sea's surface, given the sun's ray's reach below the land
// near it (terrainReachBelowLandKm's, at most TERRAIN_SHADOW_MAX_KM; the sea's light forms it with
// its reflected ray's): false where the ray stands above all the land near it may rise to as far as
// the march reaches: along a sea floor (continent value below 0, never above sea level 0), and along
// low coasts. The open sea then pays no march: a dozen height fields a pixel, which doubled the
// ocean pass where nothing could shadow it. A sea level below 0, or no slope bound, always marches.
bool terrainShadowMayReachSeaWithin(float reachKm, float seaLevelM, float continentLipschitz) {
    return seaLevelM < 0.0f || !(continentLipschitz > 0.0f) || reachKm > 0.0f;
}
// The same at the sea's point `up` (the march from `seaLevelM`), the reach formed here.
bool terrainShadowMayReachSea(vec3 up, vec3 sun, float seaLevelM, float planetRadiusKm, float continentLipschitz,
                              float sampleSlackRad, TerrainShape shape, samplerCube continents) {
    return terrainShadowMayReachSeaWithin(terrainReachBelowLandKm(up, seaLevelM, dot(up, sun), TERRAIN_SHADOW_MAX_KM,
                                                                  planetRadiusKm, continentLipschitz, sampleSlackRad,
                                                                  shape, continents),
                                          seaLevelM, continentLipschitz);
}
