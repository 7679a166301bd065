// The temporal march's spatial estimate (render/sky_temporal.frag; render/sky_refine.comp's
// STILL_FRAME program for the pixels whose surface changed in a still frame): this frame's
// reduced-rate samples (render/sky_sparse.frag, one pixel of each 4x4 block) around a pixel,
// weighted by their distance in the image and by how alike their surface distance is. Include
// after render/sparse_pattern.glsl, render/sky_medium.glsl and render/sky_history.glsl.
layout(binding = UNIT_SPARSE_INSCATTER) uniform sampler2D sparseInscatter;
layout(binding = UNIT_SPARSE_TRANSMITTANCE) uniform sampler2D sparseTransmittance;
layout(binding = UNIT_SPARSE_DISTANCE_ERROR) uniform sampler2D sparseDistanceError;  // distance m, history error

// This frame's samples around a pixel, summed for its spatial estimate: each weighted by its
// distance in the image (a tent four pixels wide: bilinear between samples) and by how alike its
// surface distance is; where none within four pixels is alike, those within eight; where none at
// all is (a thin surface between the samples), the best match: most alike, then nearest.
struct SpatialSum {
    SkySample near;
    float nearWeight;
    SkySample broad;
    float broadWeight;
    SkySample best;
    float bestRank;
};

SpatialSum noSamples() {
    SkySample none = SkySample(vec3(0.0), vec3(0.0));
    return SpatialSum(none, 0.0, none, 0.0, none, -1.0);
}

// The sample of the block `dxy` blocks from `block` (clamped into the frame), as both programs read
// it: its T and S (.rgb; .a: the clouds' reprojection distance, km, and opacity), its surface
// distance and the history's error there (render/sky_sparse.frag), and how far (blocks, each axis)
// its traced pixel lies from `pixel`.
struct BlockSample {
    vec4 inscatter;
    vec4 transmittance;
    vec2 distanceError;
    vec2 offset;
};

BlockSample blockSample(ivec2 block, ivec2 dxy, ivec2 pixel) {
    ivec2 b = clamp(block + dxy, ivec2(0), textureSize(sparseInscatter, 0) - 1);
    return BlockSample(texelFetch(sparseInscatter, b, 0), texelFetch(sparseTransmittance, b, 0),
                       texelFetch(sparseDistanceError, b, 0).rg,
                       abs(vec2(sparseTracedPixel(b) - pixel)) / float(SPARSE_BLOCK));
}

// The tent four pixels wide at a sample `offset` blocks away (each axis).
float sampleTent(vec2 offset) { return max(1.0 - offset.x, 0.0) * max(1.0 - offset.y, 0.0); }

// Adds a sample `offset` blocks away whose surface is `alike` the pixel's; true when it is the
// best match so far.
bool addSpatialSample(inout SpatialSum sum, SkySample here, float alike, vec2 offset) {
    float near = sampleTent(offset) * alike;
    sum.near.inscatter += near * here.inscatter;
    sum.near.transmittance += near * here.transmittance;
    sum.nearWeight += near;
    float wide = sampleTent(0.5 * offset) * alike;  // a tent 8 px wide
    sum.broad.inscatter += wide * here.inscatter;
    sum.broad.transmittance += wide * here.transmittance;
    sum.broadWeight += wide;
    // (the traced pixel itself, where it is one, ranks first among equally alike ones: its
    // reprojection distance is the pixel's own)
    float rank = alike - 1.0e-3 * (offset.x + offset.y);
    if (rank <= sum.bestRank) return false;
    sum.bestRank = rank;
    sum.best = here;
    return true;
}

SkySample spatialEstimate(SpatialSum sum) {
    if (sum.nearWeight > 1.0e-3)
        return SkySample(sum.near.inscatter / sum.nearWeight, sum.near.transmittance / sum.nearWeight);
    if (sum.broadWeight > 1.0e-3)
        return SkySample(sum.broad.inscatter / sum.broadWeight, sum.broad.transmittance / sum.broadWeight);
    return sum.best;
}

// A pixel (`distance` m to its surface, 0: none) whose surface is not its history's in a still
// frame (an edge the anti-aliasing's jitter moved across it): its own new sample where it is
// the block's traced pixel (`samples` 1), else its samples' spatial estimate (0), as the
// general reconstruction has it where there is no history.
SkySample surfaceChangedEstimate(ivec2 pixel, float distance, out float samples) {
    ivec2 block = pixel / SPARSE_BLOCK;
    SpatialSum around = noSamples();
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            BlockSample a = blockSample(block, ivec2(dx, dy), pixel);
            addSpatialSample(around, SkySample(a.inscatter.rgb, a.transmittance.rgb),
                             distanceSimilarity(distance, a.distanceError.x), a.offset);
        }
    }
    bool traced = sparseTracedPixel(block) == pixel;
    samples = traced ? 1.0 : 0.0;
    return traced ? SkySample(texelFetch(sparseInscatter, block, 0).rgb, texelFetch(sparseTransmittance, block, 0).rgb)
                  : spatialEstimate(around);
}
