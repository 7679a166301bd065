// The reduced-rate march (pass "sky march"): drawn over a target a quarter of the frame's
// size on each side, it traces one pixel of each 4x4 block (render/sparse_pattern.glsl)
// through air and clouds exactly as the full-rate sky pass does (render/sky.frag), with a
// start jitter that moves at every visit; render/sky_temporal.frag builds the full frame
// from these samples and the history. Each sample also says how far the history was from it
// (historyError below), which decides where the reconstruction marches again at full rate.
#include "common/frame_uniforms.glsl"
// LIGHT_SHAFTS_TERRAIN (the terrain's shadows in the air) comes from the program builder, 1 only
// when the preset asks for light shafts (src/render/atmosphere_program.h).
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/water.glsl"
#include "render/sky_air.glsl"
#include "render/sparse_pattern.glsl"
#include "render/sky_history.glsl"

// The stencil's test before the shader, where the pass splits its blocks by it
// (src/render/renderer.cpp, drawSkyMarch): the march's statistics writes would otherwise hold it
// back. (No depth is written, and nothing is discarded.)
layout(early_fragment_tests) in;
layout(binding = UNIT_SURFACE_RADIANCE) uniform sampler2D surfaceRadiance;
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;

layout(location = 0) out vec4 outInscatter;      // S, reprojection distance km
layout(location = 1) out vec4 outTransmittance;  // T, the clouds' opacity
layout(location = 2) out vec2 outDistanceError;  // the traced pixel's surface distance, m; historyError below

// How far the history, reprojected to the traced pixel as the reconstruction reads it (not
// clamped), is from the new sample there: the relative difference of the radiance's
// luminance, (now - then) / max(now, then), positive where the sample is brighter; 1 where
// there is nothing to reproject, 0 without a history. The reconstruction marks the pixels
// around a sample with a large one for a full-rate march (what moved in a way the
// reprojection cannot follow: parallax between layers of cloud, a grazing ray's point sample),
// and scales the history between the samples by a small one (light that changed).
float historyError(ivec2 pixel, vec3 dir, float distance, AirMarch a) {
    if (frame.historyValid < 0.5) return 0.0;
    vec3 behind = behindTheAir(dir, texelFetch(surfaceRadiance, pixel, 0).rgb, distance);
    SkySample history;
    float samples, weight, contrast;
    readHistory(previousPixel(dir, a.reprojectionKm, a.cloudOpacity > CLOUDY_OPACITY),
                previousSurfaceDistance(dir, distance), behind, history, samples, weight, contrast);
    if (weight <= 0.05) return 1.0;
    float now = luminance(a.transmittance * behind + a.inscatter);
    float then = luminance(history.transmittance * behind + history.inscatter);
    return (now - then) / max(max(now, then), 1.0e-6);
}

void main() {
    ivec2 block = ivec2(gl_FragCoord.xy);
    ivec2 pixel = sparseTracedPixel(block);
    vec2 ndc = pixelCentreNdc(vec2(pixel) + 0.5);
    float distance = texelFetch(surfaceDistance, pixel, 0).r;
    vec3 dir = worldRayFromNdc(ndc);
    AirMarch a = marchAir(dir, distance, sparseJitter(block));
    outInscatter = vec4(min(a.inscatter, vec3(MAX_HDR_RADIANCE)), a.reprojectionKm);
    outTransmittance = vec4(a.transmittance, a.cloudOpacity);
    // The reconstruction reads these with each sample (one read instead of a read of the
    // surface distance at the traced pixel besides). A still frame's program (STILL_FRAME, picked
    // with render/sky_temporal.frag's) leaves the history's error out: only the general
    // reconstruction reads it, and its read of the history was an eighth of this pass (`ground`,
    // 1280x720 on llvmpipe: 41 -> 35 ms).
#ifdef STILL_FRAME
    outDistanceError = vec2(distance, 0.0);
#else
    outDistanceError = vec2(distance, historyError(pixel, dir, distance, a));
#endif
}
