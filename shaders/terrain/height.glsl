// Terrain height, normal and material over the sphere, shared by GLSL and C++.
//
// Include after noise/simplex.glsl. Written in the subset of GLSL that is also C++
// (STYLE habit 1, see noise/simplex.glsl for the rules; plus samplerCube and textureLod,
// which terrain/height.cpp supplies as the CPU map and noise::sampleContinents):
// terrain/height.cpp includes the very same text into namespace planet::terrain::glsl, so
// tests/test_terrain_height.cpp checks what the GPU runs, in float on both sides.
//
// The height field (Michelic §3 and §6: baked continents plus layered 3D simplex noise
// sampled at the direction, so there are no seams and no polar distortion):
//   e = continentValue(d, continents): the baked continents cube map (noise/continents.h)
//       sampled at d with GL_LINEAR and seamless filtering, in [-1, 1]; the coast is
//       e = 0 (the bake places it so that a chosen share of the sphere is sea), e > 0 is land;
//   sea  (e < 0): h = -oceanDepth * C(-e / TERRAIN_SHELF_WIDTH, mSea), a continental shelf
//                 falling to a flat abyssal plain at exactly -oceanDepth;
//   land (e >= 0): h = maxHeight * (TERRAIN_LOWLAND_SHARE * C(e / TERRAIN_LOWLAND_WIDTH, mLand)
//                       + (1 - TERRAIN_LOWLAND_SHARE) * S(0, TERRAIN_INLAND_WIDTH, e) * m),
//                 m = mountains (mix of fBm and ridged fBm at d * mountainFrequency, squared, in [0, 1];
//                 mountainOctaves layers, Michelic Table 1's "noise layers"; 0 layers: m = 0,
//                 the continents alone) weighted by how far inland we are, so coasts are gentle;
// S is smoothstep (zero slope at both ends). C(t, m) is the cubic from 0 to 1 on [0, 1]
// with slope m at 0 and 0 at 1 (m = 0 is smoothstep): the coast has a slope, the same
// dh/de on both sides (terrainCoastSlope), so h and its gradient are continuous across it,
// and sea level crosses the ground at an angle. (With smoothstep on both sides the ground
// was flat at the coast: kilometre-wide flats within centimetres of sea level, where the
// mesh's interpolation, not the height field, decided what was wet.) h lies in
// [-oceanDepth, maxHeight] (clamped against float rounding).
//
// The normal (terrainNormal) is analytic: the 3D gradient of h (chain rule through the
// smoothsteps, the continents' baked gradient channels and the noise gradients of
// simplexNoiseGrad), projected onto the tangent plane, gives the normal of the surface
// r(d) = R + h(d):
//   n = normalize(d - grad_T h / (R + h)),
// exact for the mountains, independent of any mesh, so lighting does not change when the
// tessellation does. The continents' gradient is the fBm's analytic gradient at the texel
// centres, filtered like the elevation: continuous, where the filtered elevation is linear
// between texel centres and its own slope jumps at each of them (facets); the two agree
// over a texel to the map's resolution (tests measure it). Caveat: ridged fBm has a crease
// at each crest (|noise| at noise = 0); there the normal jumps, as the surface does.
//
// Materials (terrainMaterial): a hard rule in priority order, and terrainMaterialWeight, its
// smooth version for blending (weights sum to 1, equal to the hard rule away from thresholds).

// Material ids, numbered in the order the rule tests them (see terrainMaterial).
const int TERRAIN_MATERIAL_SEA_FLOOR = 0;
const int TERRAIN_MATERIAL_ROCK = 1;
const int TERRAIN_MATERIAL_SNOW = 2;
const int TERRAIN_MATERIAL_SAND = 3;  // beach sand
const int TERRAIN_MATERIAL_GRASS = 4;
const int TERRAIN_MATERIAL_COUNT = 5;

// Shape of the height field. Continent-value distances from the coast (the map's units:
// each side scaled to reach -1 and +1): the shelf's descent to the abyssal plain, the
// lowlands' rise, and the rise of the mountains' weight from 0 at the coast to 1.
const float TERRAIN_SHELF_WIDTH = 0.2f;
const float TERRAIN_LOWLAND_WIDTH = 0.4f;
const float TERRAIN_INLAND_WIDTH = 0.35f;
// Share of maxHeight that lowlands take; mountains take the rest.
const float TERRAIN_LOWLAND_SHARE = 0.1f;

// Material rule thresholds (see terrainMaterial).
const float TERRAIN_BEACH_DEPTH_M = 20.0f;          // sand down to 20 m below sea level, sea floor below
const float TERRAIN_BEACH_HEIGHT_M = 3.0f;          // sand up to 3 m above sea level (a few hundred m of beach at the coast's slope)
// Rise over run above which the ground is bare rock: 0.2, about 11 deg. Low for a real slope,
// but this height field has no detail finer than its last octave (about 30 km across at the
// default 6 octaves of frequency 40), and slopes averaged over that are gentle: on the default
// planet's land the median is 0.05, the 99th percentile 0.24 (0.06 and 0.29 at 10 octaves),
// so 0.2 leaves the steepest few percent rock. (Measured on the first default mountains, 6
// octaves from 40 per radius; the current default, 8 from 120, is rougher and has more rock.)
const float TERRAIN_ROCK_SLOPE = 0.2f;
const float TERRAIN_SNOW_LINE_EQUATOR_M = 5200.0f;  // snow line at the equator ...
const float TERRAIN_SNOW_FREE_LATITUDE = 1.3089969f;  // ... falling to 0 m at 75 deg (rad)
// Half widths of the blend bands around each threshold (terrainMaterialWeight).
const float TERRAIN_BLEND_HEIGHT_M = 5.0f;   // sea floor / sand / grass
const float TERRAIN_BLEND_SNOW_M = 100.0f;   // snow line
const float TERRAIN_BLEND_SLOPE = 0.02f;     // rock

// The parameters of terrain/terrain_params.h that the shader takes, in float (the
// continents' parameters went into the baked map). A std140 uniform block can hold it:
// every member sits at its std140 offset (the vec4 first, then 4-byte scalars, padded to
// 48 bytes), and terrain/height.cpp static_asserts the same layout for the C++ mirror.
struct TerrainShape {
    vec4 mountainOffset;       // noise-space offset of the mountains (xyz; from the seed), w unused
    float maxHeight;           // m above sea level, >= 0
    float oceanDepth;          // m below sea level, >= 0
    float mountainFrequency;   // per planet radius
    float ridgedWeight;        // [0, 1]
    int mountainOctaves;       // noise layers, [0, 10]; 0: continents only
    float padding0;
    float padding1;
    float padding2;
};

vec3 terrainXyz(vec4 v) { return vec3(v.x, v.y, v.z); }

// smoothstep(edge0, edge1, x) and its derivative d/dx.
float terrainSmoothstepGrad(float edge0, float edge1, float x, OUT(float) derivative) {
    float t = clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    derivative = 6.0f * t * (1.0f - t) / (edge1 - edge0);
    return t * t * (3.0f - 2.0f * t);
}

// C(t, m) of the header and its derivative dC/dt: the cubic with C(0) = 0, C'(0) = m,
// C(1) = 1, C'(1) = 0, for t clamped to [0, 1]; monotonic for m in [0, 3].
float terrainCoastRamp(float t, float m, OUT(float) derivative) {
    float x = clamp(t, 0.0f, 1.0f);
    float inside = t > 0.0f && t < 1.0f ? 1.0f : 0.0f;
    derivative = inside * (m + 2.0f * (3.0f - 2.0f * m) * x + 3.0f * (m - 2.0f) * x * x);
    return x * (m + x * ((3.0f - 2.0f * m) + x * (m - 2.0f)));
}

// dh/de at the coast, m per unit of continent value, the same on both sides: half the
// steepest that keeps both ramps monotonic (slope m <= 3 on each side), so the shallows and
// the coastal plain keep most of their shape.
float terrainCoastSlope(TerrainShape shape) {
    float sea = 3.0f * shape.oceanDepth / TERRAIN_SHELF_WIDTH;
    float land = 3.0f * TERRAIN_LOWLAND_SHARE * shape.maxHeight / TERRAIN_LOWLAND_WIDTH;
    return 0.5f * min(sea, land);
}

// The continent value at a direction, in [-1, 1] (> 0 is land), and its gradient with
// respect to the direction (tangential, per radian): one bilinear fetch of the baked map
// (Michelic §6), elevation in x, gradient in y, z, w. Level 0 explicitly: the map has no
// mipmaps, and this runs in stages without implicit derivatives.
float continentValueGrad(vec3 unitDirection, samplerCube continents, OUT(vec3) gradient) {
    vec4 texel = textureLod(continents, unitDirection, 0.0f);
    gradient = vec3(texel.y, texel.z, texel.w);
    return texel.x;
}

float continentValue(vec3 unitDirection, samplerCube continents) {
    vec3 unused;
    return continentValueGrad(unitDirection, continents, unused);
}

// Filtering by footprint. A pixel that covers many of an octave's features must show their
// average, not one of them (a far view is the mean of what a closer view shows; sampling it
// is what turned snow and rock into speckle from space). So each octave fades out as its
// features shrink below the footprint (terrainOctaveFade), a faded octave contributes its
// mean value instead of a sample, and the variance it no longer shows is carried along, so
// that what depends on it nonlinearly (the squared mountains, the slope and snow rules)
// sees the spread under the pixel: filter moments, not samples (the spirit of Toksvig's
// and LEAN mapping's normal variance). A footprint of 0 gives the unfiltered field exactly.
//
// Moments of one octave's value v = mix(0.5 + 0.5 n, (1 - |n|)^2, w) of simplex noise n and
// of its gradient, over the noise's domain (tests/test_terrain_height.cpp re-measures them):
// the fBm and ridged parts are uncorrelated (one is odd in n, the other even), so the
// mixture's moments are the (1 - w)^2 and w^2 weighted sums of these.
const float TERRAIN_FBM_OCTAVE_MEAN = 0.5f;
const float TERRAIN_FBM_OCTAVE_VARIANCE = 0.0358f;
const float TERRAIN_FBM_OCTAVE_GRADIENT_MS = 2.163f;  // mean |grad v|^2, per noise unit
const float TERRAIN_RIDGED_OCTAVE_MEAN = 0.5373f;
const float TERRAIN_RIDGED_OCTAVE_VARIANCE = 0.0799f;
const float TERRAIN_RIDGED_OCTAVE_GRADIENT_MS = 17.87f;
// An octave is kept whole while the footprint spans under a quarter of its lattice cell and
// gone at half a cell (two pixels per feature: the Nyquist limit of what a pixel can show).
const float TERRAIN_FILTER_KEEP = 0.25f;
const float TERRAIN_FILTER_DROP = 0.5f;

// How much of an octave a footprint shows, in [0, 1]: `cells` is the footprint in the
// octave's lattice cells (footprint in noise units times the octave's frequency).
float terrainOctaveFade(float cells) { return 1.0f - smoothstep(TERRAIN_FILTER_KEEP, TERRAIN_FILTER_DROP, cells); }

// One octave of the mountains from its simplex noise n: mix(0.5 + 0.5 n, (1 - |n|)^2,
// ridgedWeight), and its derivative d/dn (`slope`).
float terrainMountainOctave(float n, float ridgedWeight, OUT(float) slope) {
    float fbmShare = 1.0f - ridgedWeight;
    float ridge = 1.0f - abs(n);
    slope = fbmShare * 0.5f - ridgedWeight * 2.0f * ridge * sign(n);
    return fbmShare * (0.5f + 0.5f * n) + ridgedWeight * ridge * ridge;
}

// Mountains at noise-space point p, in [0, 1], and the gradient d/dp: per octave (lacunarity 2,
// gain 0.5) mix(0.5 + 0.5 n, (1 - |n|)^2, ridgedWeight) of simplex noise n, normalised like
// fbm; ridgedWeight 0 is 0.5 + 0.5 fbm(p), 1 is ridgedFbm(p). One noise evaluation per octave;
// 0 octaves (continents only) is 0.
// Filtered over a footprint of `footprint` noise units (0: none): the octaves too fine for
// it contribute their mean; `variance` and `gradientVariance` are the value's and the
// gradient's (mean |.|^2) variance they leave under the footprint. Octaves past the
// footprint cost no noise evaluation, so a far view is cheaper.
float terrainMountainsGradFiltered(vec3 p, int octaves, float ridgedWeight, float footprint, OUT(vec3) gradient,
                                   OUT(float) variance, OUT(float) gradientVariance) {
    int count = clamp(octaves, 0, 10);
    gradient = vec3(0.0f);
    variance = 0.0f;
    gradientVariance = 0.0f;
    if (count == 0) return 0.0f;
    float fbmShare = 1.0f - ridgedWeight;
    float octaveMean = fbmShare * TERRAIN_FBM_OCTAVE_MEAN + ridgedWeight * TERRAIN_RIDGED_OCTAVE_MEAN;
    float octaveVariance =
        fbmShare * fbmShare * TERRAIN_FBM_OCTAVE_VARIANCE + ridgedWeight * ridgedWeight * TERRAIN_RIDGED_OCTAVE_VARIANCE;
    float octaveGradientMs = fbmShare * fbmShare * TERRAIN_FBM_OCTAVE_GRADIENT_MS +
                             ridgedWeight * ridgedWeight * TERRAIN_RIDGED_OCTAVE_GRADIENT_MS;
    // The octaves the footprint shows (fade > 0) come first, each finer one fading sooner: their
    // noise is evaluated in a loop of their own, so that a group of pixels that shows none (from
    // orbit) takes no noise at all (a software renderer runs an if's code for every pixel, masked,
    // but leaves a loop that none of them enters); the rest add their mean and variance alone.
    int shown = 0;
    for (float f = 1.0f; shown < count && terrainOctaveFade(footprint * f) > 0.0f; f *= 2.0f) shown++;
    float sum = 0.0f;
    float total = 0.0f;
    float amplitude = 1.0f;
    float frequency = 1.0f;
    int k = 0;
    for (; k < shown; k++) {
        float fade = terrainOctaveFade(footprint * frequency);
        vec3 g;
        float n = simplexNoiseGrad(p * frequency, g);
        float slope;
        float octaveValue = terrainMountainOctave(n, ridgedWeight, slope);
        float value = fade * octaveValue + (1.0f - fade) * octaveMean;
        gradient += (fade * amplitude * frequency * slope) * g;
        float hidden = 1.0f - fade * fade;  // the share of this octave's variance the footprint averages away
        variance += hidden * amplitude * amplitude * octaveVariance;
        gradientVariance += hidden * amplitude * amplitude * frequency * frequency * octaveGradientMs;
        sum += amplitude * value;
        total += amplitude;
        frequency *= 2.0f;
        amplitude *= 0.5f;
    }
    for (; k < count; k++) {  // not shown: the mean, all of the variance hidden
        variance += amplitude * amplitude * octaveVariance;
        gradientVariance += amplitude * amplitude * frequency * frequency * octaveGradientMs;
        sum += amplitude * octaveMean;
        total += amplitude;
        frequency *= 2.0f;
        amplitude *= 0.5f;
    }
    gradient /= total;
    variance /= total * total;
    gradientVariance /= total * total;
    return sum / total;
}

float terrainMountainsGrad(vec3 p, int octaves, float ridgedWeight, OUT(vec3) gradient) {
    float variance;
    float gradientVariance;
    return terrainMountainsGradFiltered(p, octaves, ridgedWeight, 0.0f, gradient, variance, gradientVariance);
}

// The height from its parts: the continent value e and its gradient (per radian), and on
// land the mountains' noise (terrainMountainsGradFiltered) with its gradient (per noise
// unit) and variances; see terrainHeightGradFiltered.
float terrainHeightFromParts(TerrainShape shape, float e, vec3 continentGradient, float noise, vec3 noiseGradient,
                             float noiseVariance, float noiseGradientVariance, OUT(vec3) gradient,
                             OUT(float) heightVariance, OUT(float) gradientVariance) {
    float height;
    float coastSlope = terrainCoastSlope(shape);
    heightVariance = 0.0f;
    gradientVariance = 0.0f;
    if (e < 0.0f) {
        float dShelf;
        float mSea = shape.oceanDepth > 0.0f ? coastSlope * TERRAIN_SHELF_WIDTH / shape.oceanDepth : 0.0f;
        float shelf = terrainCoastRamp(-e / TERRAIN_SHELF_WIDTH, mSea, dShelf);
        height = -shape.oceanDepth * shelf;
        // d(-D C(-e / W)) = (D / W) C'(-e / W) de
        gradient = (shape.oceanDepth * dShelf / TERRAIN_SHELF_WIDTH) * continentGradient;
    } else {
        float dLowland;
        float dInland;
        float lowlandHeight = TERRAIN_LOWLAND_SHARE * shape.maxHeight;
        float mLand = lowlandHeight > 0.0f ? coastSlope * TERRAIN_LOWLAND_WIDTH / lowlandHeight : 0.0f;
        float lowland = terrainCoastRamp(e / TERRAIN_LOWLAND_WIDTH, mLand, dLowland);
        dLowland /= TERRAIN_LOWLAND_WIDTH;
        float inland = terrainSmoothstepGrad(0.0f, TERRAIN_INLAND_WIDTH, e, dInland);
        // Mountains squared: most of the land stays low, peaks are rare (mean land height
        // about 1/4 of maxHeight instead of 1/2). Filtered: E[noise^2] = mean^2 + variance.
        float mountains = noise * noise + noiseVariance;
        vec3 mountainGradient = (2.0f * noise) * noiseGradient;
        float mountainShare = 1.0f - TERRAIN_LOWLAND_SHARE;
        float mountainScale = shape.maxHeight * mountainShare * inland;
        height = shape.maxHeight * TERRAIN_LOWLAND_SHARE * lowland + mountainScale * mountains;
        gradient = shape.maxHeight * ((TERRAIN_LOWLAND_SHARE * dLowland + mountainShare * dInland * mountains) *
                                          continentGradient +
                                      (mountainShare * inland * shape.mountainFrequency) * mountainGradient);
        // First order in the hidden octaves: d(noise^2) = 2 noise d(noise).
        float spread = 2.0f * noise * mountainScale;
        heightVariance = spread * spread * noiseVariance;
        gradientVariance = spread * spread * shape.mountainFrequency * shape.mountainFrequency * noiseGradientVariance;
    }
    return clamp(height, -shape.oceanDepth, shape.maxHeight);
}

// The mountains' value (noise^2 plus the variance a footprint hides) is at most 1 where the
// octaves' simplex noise stays in [-1, 1]; the bound below allows a tenth more.
const float TERRAIN_MOUNTAINS_BOUND = 1.1f;

// The highest the height field rises where the continent value is at most e: every part of
// terrainHeightFromParts rises with e (the shelf, the lowlands' ramp, the mountains' inland
// weight), so its value at e with the mountains at their bound is the bound. With the
// continents map's slope bound, the most that land within a distance of a point can rise
// (ocean/screen_space_reflections.glsl's reachBelowLand): near a coast a few hundred metres,
// where maxHeight is 8 km.
// (terrainHeightFromParts's height alone, both sides formed and one picked: it runs per pixel,
// where a software renderer would run both sides of an if anyway, and their gradients for nothing.)
// The land's height at continent value e >= 0 is lowlandM + mountainScaleM x the mountains' value
// (noise^2 plus the variance a footprint hides; terrainHeightFromParts): its two parts, without
// their gradients.
void terrainLandParts(TerrainShape shape, float e, OUT(float) lowlandM, OUT(float) mountainScaleM) {
    float unused;
    float lowlandHeight = TERRAIN_LOWLAND_SHARE * shape.maxHeight;
    float mLand = lowlandHeight > 0.0f ? terrainCoastSlope(shape) * TERRAIN_LOWLAND_WIDTH / lowlandHeight : 0.0f;
    lowlandM = lowlandHeight * terrainCoastRamp(e / TERRAIN_LOWLAND_WIDTH, mLand, unused);
    mountainScaleM = shape.maxHeight * (1.0f - TERRAIN_LOWLAND_SHARE) *
                     terrainSmoothstepGrad(0.0f, TERRAIN_INLAND_WIDTH, e, unused);
}

float terrainHeightBound(TerrainShape shape, float e) {
    float unused;
    float mSea = shape.oceanDepth > 0.0f ? terrainCoastSlope(shape) * TERRAIN_SHELF_WIDTH / shape.oceanDepth : 0.0f;
    float sea = -shape.oceanDepth * terrainCoastRamp(-e / TERRAIN_SHELF_WIDTH, mSea, unused);
    float lowlandM;
    float mountainScaleM;
    terrainLandParts(shape, e, lowlandM, mountainScaleM);
    float land = lowlandM + mountainScaleM * TERRAIN_MOUNTAINS_BOUND;
    return clamp(e < 0.0f ? sea : land, -shape.oceanDepth, shape.maxHeight);
}

// Height above sea level in metres at a direction, in [-oceanDepth, maxHeight], and its
// gradient with respect to the direction as a point in R^3 (m per unit; only the tangential
// part is meaningful on the sphere: m per radian), filtered over a footprint of
// `footprint` radians (0: none; see terrainMountainsGradFiltered): then the mean height over
// it, the gradient of that mean, and the height's and the gradient's (m^2 per radian^2)
// variance under the footprint. The continents are the baked map's, bilinear and unfiltered:
// their features are hundreds of km across.
float terrainHeightGradFiltered(vec3 unitDirection, TerrainShape shape, samplerCube continents, float footprint,
                                OUT(vec3) gradient, OUT(float) heightVariance, OUT(float) gradientVariance) {
    vec3 continentGradient;
    float e = continentValueGrad(unitDirection, continents, continentGradient);
    float noise = 0.0f;
    vec3 noiseGradient = vec3(0.0f);
    float noiseVariance = 0.0f;
    float noiseGradientVariance = 0.0f;
    // The mountains only on land: the sea floor takes no octave. A count of none rather than an
    // if: a software renderer runs an if's code for every pixel, every octave, but leaves the
    // octaves' loop after its first turn where no pixel of a group is on land (the open sea:
    // from orbit the far field's sea pixels and the terrain shadow's samples, about 3 ms).
    int octaves = e >= 0.0f ? shape.mountainOctaves : 0;
    noise = terrainMountainsGradFiltered(unitDirection * shape.mountainFrequency + terrainXyz(shape.mountainOffset),
                                         octaves, shape.ridgedWeight, footprint * shape.mountainFrequency,
                                         noiseGradient, noiseVariance, noiseGradientVariance);
    return terrainHeightFromParts(shape, e, continentGradient, noise, noiseGradient, noiseVariance,
                                  noiseGradientVariance, gradient, heightVariance, gradientVariance);
}

float terrainHeightGrad(vec3 unitDirection, TerrainShape shape, samplerCube continents, OUT(vec3) gradient) {
    float heightVariance;
    float gradientVariance;
    return terrainHeightGradFiltered(unitDirection, shape, continents, 0.0f, gradient, heightVariance,
                                     gradientVariance);
}

float terrainHeight(vec3 unitDirection, TerrainShape shape, samplerCube continents) {
    vec3 unused;
    return terrainHeightGrad(unitDirection, shape, continents, unused);
}

// The height field near the camera, without float's rounding of planet-sized numbers.
// terrainHeight takes a float direction: its components round to 6e-8, half a metre on an
// Earth-sized planet, so heights evaluated there step by centimetres every half metre, which
// is nothing for the mesh but everything for detail 0.5 m across seen from 2 m. Near the
// camera the same field is evaluated from the point's offset to the camera instead: the
// direction's change from the camera's is formed exactly from the camera-relative point
// (terrainNearDirectionChange), each mountain octave's noise point is the camera's (a
// lattice point and an offset from it, formed in double on the CPU: terrain/height.h
// makeTerrainNear) plus that change, and the continents, whose features are hundreds of km
// across, are the camera's value plus the gradient of the filtered map times the change
// (first order). Used within TERRAIN_NEAR_RANGE_M of the camera, where it agrees with
// terrainHeight to that function's own rounding (tests/test_terrain_near.cpp: centimetres;
// the continents' first order adds a few tenths of a metre by 2-3 km).
const float TERRAIN_NEAR_RANGE_M = 3000.0f;
// Camera-relative positions plus the camera's position modulo this (formed in double) are
// small numbers that are exact near the camera and jump by a whole number of this when the
// camera crosses it: world-fixed coordinates for anything whose period divides it (the
// ground detail's textures).
const float TERRAIN_NEAR_WRAP_M = 4096.0f;

struct TerrainNear {
    vec4 cameraUp;          // xyz: unit direction from the planet centre to the camera; w: |camera| (m)
    vec4 cameraPlace;       // xyz: the camera's world position modulo TERRAIN_NEAR_WRAP_M (m); w: its
                            // altitude above the planet radius (m), both formed in double
    vec4 continent;         // x: the continent value at the camera's direction; yzw: its gradient (per radian)
    vec4 octaveLattice[10]; // mountain octave k's noise point at the camera: a lattice point (skewed
    vec4 octaveOffset[10];  // coordinates modulo 289) and the offset from it (unskewed), xyz
    vec4 patchLattice;      // the ground's patches' noise point at the camera (terrainPatchesNear): a lattice
    vec4 patchOffset;       // point (skewed, modulo 289) and the offset from it (unskewed), xyz
};

// The change of direction from the camera's to the point at `pointFromCamera` (m, world
// axes), exactly: d(C + X) - d(C) = (X - up * rise) / |C + X|, where rise = |C + X| - |C| =
// (2 |C| up.X + X.X) / (|C + X| + |C|) subtracts nothing of planet size.
vec3 terrainNearDirectionChange(vec3 pointFromCamera, TerrainNear near, OUT(float) rise, OUT(float) radius) {
    vec3 up = terrainXyz(near.cameraUp);
    float c = near.cameraUp.w;
    float twiceAlong = 2.0f * c * dot(up, pointFromCamera) + dot(pointFromCamera, pointFromCamera);
    radius = sqrt(c * c + twiceAlong);
    rise = twiceAlong / (radius + c);
    return (pointFromCamera - up * rise) / radius;
}

// The ground detail's coarse scale (terrain/detail.glsl): the meadow's dry and lush patches and the
// ground's gentle relief at the point at `pointFromCamera` (m, world axes), a field fixed to the world,
// of mean 0 and unit RMS, and its gradient (per m, world axes): one octave of simplex noise over the
// world position in cells TERRAIN_PATCH_CELL_M across, its noise point the camera's (formed in
// double: TerrainNear) plus the camera-relative point, exact near the camera and with no period.
// The detail texture's coarse scale, which this replaced, repeats every 32 m along its projection's
// axes: a lattice of blotches seen from 20 m up.
const float TERRAIN_PATCH_CELL_M = 16.0f;
// 1 / the noise's RMS over the world, and the RMS of the field's slope along the ground (per m, both
// components) then (tests/test_terrain_near.cpp measures both).
const float TERRAIN_PATCH_RMS_SCALE = 2.66f;
const float TERRAIN_PATCH_SLOPE_RMS = 0.399f;
float terrainPatchesNear(vec3 pointFromCamera, TerrainNear near, OUT(vec3) gradient) {
    vec3 q = terrainXyz(near.patchOffset) + pointFromCamera * (1.0f / TERRAIN_PATCH_CELL_M);
    vec3 g;
    float n = simplexNoiseGradFrom(terrainXyz(near.patchLattice), q, g);
    gradient = g * (TERRAIN_PATCH_RMS_SCALE / TERRAIN_PATCH_CELL_M);
    return TERRAIN_PATCH_RMS_SCALE * n;
}

// Height (m above sea level) at the point at `pointFromCamera` (m, world axes) and its
// gradient with respect to the direction, as terrainHeightGrad (unfiltered), but exact to
// float near the camera (see TerrainNear).
float terrainHeightNearGrad(vec3 pointFromCamera, TerrainNear near, TerrainShape shape, OUT(vec3) gradient) {
    float rise;
    float radius;
    vec3 change = terrainNearDirectionChange(pointFromCamera, near, rise, radius);
    vec3 continentGradient = vec3(near.continent.y, near.continent.z, near.continent.w);
    float e = near.continent.x + dot(continentGradient, change);
    float noise = 0.0f;
    vec3 noiseGradient = vec3(0.0f);
    int count = clamp(shape.mountainOctaves, 0, 10);
    if (e >= 0.0f && count > 0) {  // terrainMountainsGradFiltered at a footprint of 0, octave by octave
        float sum = 0.0f;
        float total = 0.0f;
        float amplitude = 1.0f;
        float frequency = 1.0f;
        for (int k = 0; k < 10; k++) {
            if (k >= count) break;
            vec3 q = terrainXyz(near.octaveOffset[k]) + change * (shape.mountainFrequency * frequency);
            vec3 g;
            float n = simplexNoiseGradFrom(terrainXyz(near.octaveLattice[k]), q, g);
            float slope;
            sum += amplitude * terrainMountainOctave(n, shape.ridgedWeight, slope);
            noiseGradient += (amplitude * frequency * slope) * g;
            total += amplitude;
            frequency *= 2.0f;
            amplitude *= 0.5f;
        }
        noise = sum / total;
        noiseGradient /= total;
    }
    float heightVariance;
    float gradientVariance;
    return terrainHeightFromParts(shape, e, continentGradient, noise, noiseGradient, 0.0f, 0.0f, gradient,
                                  heightVariance, gradientVariance);
}

// One Newton step of terrainRayHitNearSteps at the point x = d t (camera-relative, d the unit ray)
// where the height field's height h and gradient are known: f, the ray's height above the ground
// there, and df/dt; `radial`, the unit vertical at x.
float terrainRayNewtonTerms(vec3 x, vec3 d, TerrainNear near, float h, vec3 gradient, OUT(float) df,
                            OUT(vec3) radial) {
    float rise;
    float radius;
    terrainNearDirectionChange(x, near, rise, radius);
    radial = (terrainXyz(near.cameraUp) * near.cameraUp.w + x) / radius;
    vec3 tangential = gradient - dot(gradient, radial) * radial;
    df = dot(d, radial) - dot(tangential, d) / radius;
    return near.cameraPlace.w + rise - h;
}

// Where the ray from the camera through `start` (m, camera-relative: a point near the
// surface, such as the mesh's) meets the height field near the camera: Newton's method on
// f(t) = altitude(t d) - h(t d), the ray's height above the ground, from t = |start|, at most
// `steps` steps (one height evaluation each). The result depends on the ray alone, not on
// the start (the mesh, which moves with the tessellation), once converged: true then, with
// the point in `hit`; false where the ray does not descend towards the ground there (a
// silhouette) or the step would leave the start's neighbourhood (another crossing), and `hit`
// is then the start moved along the local vertical onto the height field: on the ground, near
// the ray, though it moves with the mesh. (Taking no detail there left holes: at 160 x 90 the
// coarser mesh's starts failed along whole rows at the crest of a slope and in the near
// foreground, flat streaks that the aliasing test counted.) Converged: the last step was
// small (the next would be smaller still), or, with a budget of one step, the step was taken:
// Newton's error after it is second order in the start's, so a start centimetres off the
// ground (the mesh's) lands a fraction of a millimetre from the crossing. (Trusting only a
// small first step put a third of the `mountains` foreground on the mesh's point: its
// aliasing error went from 2.3 to 4.0 %.)
bool terrainRayHitNearSteps(vec3 start, TerrainNear near, TerrainShape shape, int steps, OUT(vec3) hit) {
    float t0 = length(start);
    vec3 d = start / t0;
    float t = t0;
    float newtonStep = 1.0e30f;
    vec3 onTheGround = start;
    for (int i = 0; i < 4; i++) {
        if (i >= steps) break;
        vec3 x = d * t;
        vec3 gradient;
        float h = terrainHeightNearGrad(x, near, shape, gradient);
        float df;
        vec3 radial;
        float f = terrainRayNewtonTerms(x, d, near, h, gradient, df, radial);
        if (i == 0) onTheGround = start - radial * f;
        if (df > -1.0e-4f) break;
        newtonStep = f / df;
        t -= newtonStep;
        if (abs(newtonStep) < 1.0e-4f * t) break;
    }
    // Converged to 0.1 % of the distance: the float heights (0.5 mm at a few km) over a
    // grazing ray's descent leave no better, and a pixel's footprint is far larger.
    bool stepped = steps == 1 ? newtonStep < 1.0e29f : abs(newtonStep) < 1.0e-3f * t + 1.0e-3f;
    bool converged = stepped && abs(t - t0) < 0.1f * t0 + 1.0f;
    hit = converged ? d * t : onTheGround;
    return converged;
}

// terrainRayHitNearSteps's single step from `start` where the height h and gradient there are
// already known (terrainHeightNearGrad at start): the same step, no height evaluated.
bool terrainRayHitNearStepFrom(vec3 start, TerrainNear near, float h, vec3 gradient, OUT(vec3) hit) {
    float t0 = length(start);
    vec3 d = start / t0;
    float df;
    vec3 radial;
    float f = terrainRayNewtonTerms(d * t0, d, near, h, gradient, df, radial);
    float t = df > -1.0e-4f ? t0 : t0 - f / df;
    bool converged = df <= -1.0e-4f && abs(t - t0) < 0.1f * t0 + 1.0f;
    hit = converged ? d * t : start - radial * f;
    return converged;
}

// Whether a footprint of `footprintM` metres shows every mountain octave whole
// (terrainOctaveFade 1 for the finest: its lattice cell at least 1 / TERRAIN_FILTER_KEEP
// footprints): then terrainHeightGradFiltered is terrainHeightGrad exactly, with no variance.
bool terrainFootprintShowsEveryOctave(TerrainShape shape, float footprintM, float planetRadius) {
    float finestFrequency = ldexp(shape.mountainFrequency, max(shape.mountainOctaves - 1, 0));
    return footprintM / planetRadius * finestFrequency <= TERRAIN_FILTER_KEEP;
}

// terrainRayHitNearSteps to convergence: three or four height evaluations.
bool terrainRayHitNear(vec3 start, TerrainNear near, TerrainShape shape, OUT(vec3) hit) {
    return terrainRayHitNearSteps(start, near, shape, 4, hit);
}

// Unit normal of the terrain surface r(d) = planetRadius + h(d) at direction d (planetRadius
// in metres): the height gradient projected onto the tangent plane, n = normalize(d - grad_T h / r).
vec3 terrainNormalFromGradient(vec3 unitDirection, float height, vec3 gradient, float planetRadius) {
    vec3 tangential = gradient - dot(gradient, unitDirection) * unitDirection;
    return normalize(unitDirection - tangential / (planetRadius + height));
}

vec3 terrainNormal(vec3 unitDirection, TerrainShape shape, samplerCube continents, float planetRadius) {
    vec3 gradient;
    float height = terrainHeightGrad(unitDirection, shape, continents, gradient);
    return terrainNormalFromGradient(unitDirection, height, gradient, planetRadius);
}

// The terrain as a pixel with a footprint of `footprintM` metres sees it: the normal of the
// mean surface, the mean height, and the spreads (standard deviations) under the footprint
// of the height (m) and of the slope (rise over run) that the normal no longer shows.
vec3 terrainNormalFiltered(vec3 unitDirection, TerrainShape shape, samplerCube continents, float planetRadius,
                           float footprintM, OUT(float) height, OUT(float) heightSpread, OUT(float) slopeSpread) {
    vec3 gradient;
    float heightVariance;
    float gradientVariance;
    height = terrainHeightGradFiltered(unitDirection, shape, continents, footprintM / planetRadius, gradient,
                                       heightVariance, gradientVariance);
    heightSpread = sqrt(heightVariance);
    slopeSpread = sqrt(gradientVariance) / (planetRadius + height);
    return terrainNormalFromGradient(unitDirection, height, gradient, planetRadius);
}

// Slope as rise over run (tan of the angle between the normal and the local vertical up):
// 0 flat, 1 at 45 deg. |n x up| / (n . up) keeps precision on gentle slopes.
float terrainSlope(vec3 normal, vec3 up) {
    return length(cross(normal, up)) / max(dot(normal, up), 1.0e-6f);
}

// Latitude of a direction in radians, [-pi/2, pi/2] (world +Z is north).
float terrainLatitude(vec3 unitDirection) { return asin(clamp(unitDirection.z, -1.0f, 1.0f)); }

// Height of the snow line at a latitude (rad): TERRAIN_SNOW_LINE_EQUATOR_M at the equator,
// falling as 1 - (lat / TERRAIN_SNOW_FREE_LATITUDE)^2 to sea level there and staying there
// poleward: about 3300 m at 45 deg and 1300 m at 65 deg, close to Earth's climatic snow line.
float terrainSnowLine(float latitude) {
    float x = min(abs(latitude) / TERRAIN_SNOW_FREE_LATITUDE, 1.0f);
    return TERRAIN_SNOW_LINE_EQUATOR_M * (1.0f - x * x);
}

// The material at a point, from its height (m above sea level), slope (rise over run,
// terrainSlope) and latitude (rad). The first rule that holds:
//   1. height < -TERRAIN_BEACH_DEPTH_M              -> sea floor
//   2. slope > TERRAIN_ROCK_SLOPE                   -> rock (too steep for soil or snow)
//   3. height > terrainSnowLine(latitude)           -> snow (high, or anywhere above sea level
//                                                      poleward of TERRAIN_SNOW_FREE_LATITUDE)
//   4. height < TERRAIN_BEACH_HEIGHT_M              -> sand (the beach, and shallow water)
//   5. otherwise                                    -> grass
int terrainMaterial(float height, float slope, float latitude) {
    if (height < -TERRAIN_BEACH_DEPTH_M) return TERRAIN_MATERIAL_SEA_FLOOR;
    if (slope > TERRAIN_ROCK_SLOPE) return TERRAIN_MATERIAL_ROCK;
    if (height > terrainSnowLine(latitude)) return TERRAIN_MATERIAL_SNOW;
    if (height < TERRAIN_BEACH_HEIGHT_M) return TERRAIN_MATERIAL_SAND;
    return TERRAIN_MATERIAL_GRASS;
}

// How fully rule `material` of terrainMaterial holds, in [0, 1]: a smoothstep across its
// threshold, 0.5 exactly on it, 0 or 1 further than the blend half width from it.
// With spreads (standard deviations of height, m, and slope under a pixel's footprint,
// terrainNormalFiltered; 0: a point) it is the share of the footprint where the rule holds,
// approximately: each band widens by twice the spread, and the slope compared is the RMS
// slope sqrt(slope^2 + spread^2), since hidden bumps only ever steepen the ground.
float terrainMaterialCoverageSpread(int material, float height, float slope, float latitude, float heightSpread,
                                    float slopeSpread) {
    float heightBand = TERRAIN_BLEND_HEIGHT_M + 2.0f * heightSpread;
    if (material == TERRAIN_MATERIAL_SEA_FLOOR)
        return 1.0f - smoothstep(-TERRAIN_BEACH_DEPTH_M - heightBand, -TERRAIN_BEACH_DEPTH_M + heightBand, height);
    if (material == TERRAIN_MATERIAL_ROCK) {
        float slopeBand = TERRAIN_BLEND_SLOPE + 2.0f * slopeSpread;
        float rmsSlope = slopeSpread > 0.0f ? sqrt(slope * slope + slopeSpread * slopeSpread) : slope;
        return smoothstep(TERRAIN_ROCK_SLOPE - slopeBand, TERRAIN_ROCK_SLOPE + slopeBand, rmsSlope);
    }
    if (material == TERRAIN_MATERIAL_SNOW) {
        float snowLine = terrainSnowLine(latitude);
        float snowBand = TERRAIN_BLEND_SNOW_M + 2.0f * heightSpread;
        return smoothstep(snowLine - snowBand, snowLine + snowBand, height);
    }
    if (material == TERRAIN_MATERIAL_SAND)
        return 1.0f - smoothstep(TERRAIN_BEACH_HEIGHT_M - heightBand, TERRAIN_BEACH_HEIGHT_M + heightBand, height);
    return 1.0f;  // grass: whatever the rules above leave
}

float terrainMaterialCoverage(int material, float height, float slope, float latitude) {
    return terrainMaterialCoverageSpread(material, height, slope, latitude, 0.0f, 0.0f);
}

// Blend weight of `material` at a point: coverage of its rule times what the earlier rules
// leave, w_i = c_i * prod_{j < i} (1 - c_j). The weights of all materials sum to 1, vary
// smoothly, and equal the hard rule (1 for terrainMaterial's id, 0 for the others) wherever
// every threshold is further than its blend half width. With spreads: over a footprint.
struct TerrainMaterialWeights {
    float weight[TERRAIN_MATERIAL_COUNT];  // by material id
};

// Every material's weight at once (one coverage each).
TerrainMaterialWeights terrainMaterialWeightsSpread(float height, float slope, float latitude, float heightSpread,
                                                    float slopeSpread) {
    TerrainMaterialWeights w;
    float remaining = 1.0f;
    for (int id = 0; id < TERRAIN_MATERIAL_COUNT; id++) {
        float coverage = terrainMaterialCoverageSpread(id, height, slope, latitude, heightSpread, slopeSpread);
        w.weight[id] = remaining * coverage;
        remaining *= 1.0f - coverage;
    }
    return w;
}

float terrainMaterialWeightSpread(int material, float height, float slope, float latitude, float heightSpread,
                                  float slopeSpread) {
    return terrainMaterialWeightsSpread(height, slope, latitude, heightSpread, slopeSpread).weight[material];
}

float terrainMaterialWeight(int material, float height, float slope, float latitude) {
    return terrainMaterialWeightSpread(material, height, slope, latitude, 0.0f, 0.0f);
}
