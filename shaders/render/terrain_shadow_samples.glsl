// Reading the terrain shadow's samples (render/terrain_shadow.frag: the march's clearance angle at
// one pixel of each terrainShadowSpacing-square block) at a frame pixel: the surface light for
// the ground (the samples' r) and the ocean for the sea's surface (their g). Include after
// render/sample_spacing.glsl and render/block_samples.glsl, with the samples' texture declared.

// Where the samples around a pixel all clear the sun's disc by this much more than its radius
// (rad), the pixel is taken as lit without a march: the margin catches most shadows narrower
// than the samples' spacing, cast by bumps whose horizon the samples only just clear. It stays
// below terrain/terrain_shadow.glsl's TERRAIN_SHADOW_EXACT_MARGIN: the march's clearance is
// exact only up to the radius plus that.
const float TERRAIN_SHADOW_LIT_MARGIN = 0.03;

// The terrain's clearance at `pixel` from the samples' `channel` (0: the ground, 1: the sea's
// surface) around it (one, two or four: the corners of its cell of their grid), where they all
// clear the sun's disc (angular radius `radius`) by TERRAIN_SHADOW_LIT_MARGIN (lit) or all hide
// it (shadowed), or the pixel is a sample itself: true, with the clearance in `clearance`
// (left as it was otherwise). False where a shadow's edge or penumbra passes or a sample shows
// no surface (an edge on screen): the caller marches there. A shadow narrower than the samples'
// spacing that falls between samples which clear the margin is missed, as the march misses a
// ridge narrower than its own step.
bool terrainClearanceFromSamples(sampler2D samples, ivec2 pixel, int channel, float radius, inout float clearance,
                                 out float meanClearance) {
    ivec2 corners[4];
    blockSampleCorners(pixel, terrainShadowSpacing(frameHeightPixels()), textureSize(samples, 0) - 1, corners);
    float a = texelFetch(samples, corners[0], 0)[channel];
    float b = texelFetch(samples, corners[1], 0)[channel];
    float c = texelFetch(samples, corners[2], 0)[channel];
    float d = texelFetch(samples, corners[3], 0)[channel];
    float lowest = min(min(a, b), min(c, d));
    float highest = max(max(a, b), max(c, d));
    bool surface = lowest > 0.5 * TERRAIN_SHADOW_NO_SURFACE;
    bool lit = lowest >= radius + TERRAIN_SHADOW_LIT_MARGIN;
    bool shadowed = surface && highest <= -radius;
    bool onASample = corners[0] == corners[3] && surface;
    bool agree = lit || shadowed || onASample;
    if (agree) clearance = a;
    // The mean over the samples that show a surface (lit, 1 rad, where none does): a stand-in where
    // no march can be had (render/terrain_shadow_list.glsl).
    vec4 shows = vec4(greaterThan(vec4(a, b, c, d), vec4(0.5 * TERRAIN_SHADOW_NO_SURFACE)));
    float count = dot(shows, vec4(1.0));
    meanClearance = count > 0.0 ? dot(shows, vec4(a, b, c, d)) / count : 1.0;
    return agree;
}

bool terrainClearanceFromSamples(sampler2D samples, ivec2 pixel, int channel, float radius, inout float clearance) {
    float mean;
    return terrainClearanceFromSamples(samples, pixel, channel, radius, clearance, mean);
}
