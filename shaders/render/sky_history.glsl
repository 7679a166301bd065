// The temporal march's history (render/sky_temporal.frag rebuilds each pixel from it,
// render/sky_sparse.frag checks it against each new sample): where a pixel's point was in the
// previous frame, and the previous frame's T and S read there. Include after
// common/frame_uniforms.glsl.
#include "render/sky_medium.glsl"
layout(binding = UNIT_HISTORY_SKY_MEDIUM) uniform usampler2D historySkyMedium;
layout(binding = UNIT_HISTORY_SURFACE_DISTANCE) uniform sampler2D historySurfaceDistance;

// How alike two surface distances (m, 0: no surface) are for sharing a sample: 0 for sky
// against surface, 1 for sky against sky, and for two surfaces a Gaussian in the logarithm of
// their ratio (1/2: a factor of 1.65; flat ground seen at a grazing angle changes by tens of
// per cent over a few pixels and stays one surface, a hill against the valley behind it does
// not).
float distanceSimilarity(float a, float b) {
    if ((a > 0.0) != (b > 0.0)) return 0.0;
    if (a <= 0.0) return 1.0;
    float x = log(a / b) / 0.5;
    return exp(-x * x);
}

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// The history at `position` (pixels, centres at +0.5) where the previous camera saw its
// surface at `expected` m (0: sky): Catmull-Rom over 4x4 texels where the 2x2 around the point
// all show that surface (sharp: a bilinear read each frame would blur what the history holds
// over the 16 frames until a pixel is traced again), else bilinear over those of the 2x2 that
// do. `weight` is how much of the footprint matched (0: a disocclusion, no history);
// `contrast` the relative range of the radiance over the 2x2 that match, seen against `behind`
// (the surface radiance, or the sun's disc), 1 where the 2x2 straddles an edge between
// surfaces: a line or an edge in the history, which a reprojection moves only where the
// scene moved rigidly.
void readHistory(vec2 position, float expected, vec3 behind, out SkySample history, out float samples,
                 out float weight, out float contrast) {
    history = SkySample(vec3(0.0), vec3(0.0));
    samples = 0.0;
    weight = 0.0;
    ivec2 size = ivec2(frame.viewportSize);
    // The point on a texel's centre, to a thousandth of a pixel (a still camera's pixels; with only
    // the clock running, all but the clouds): that texel is the history, what the filters below
    // give there, in 2 reads instead of 24 (render/sky_temporal.frag's cost from a still camera).
    if (all(lessThan(abs(fract(position) - 0.5), vec2(1.0e-3)))) {
        ivec2 tap = ivec2(floor(position));
        bool inside = all(greaterThanEqual(tap, ivec2(0))) && all(lessThan(tap, size));
        float alike = inside ? distanceSimilarity(expected, texelFetch(historySurfaceDistance, tap, 0).r) : 0.0;
        contrast = 0.0;  // nothing read across
        if (alike > 0.0) {
            history = unpackSkyMedium(texelFetch(historySkyMedium, tap, 0), samples);
            weight = alike;
        }
        return;
    }
    float lo = 1.0e30, hi = 0.0;
    vec2 base = floor(position - 0.5);
    vec2 f = position - 0.5 - base;
    bool sharp = true;
    for (int i = 0; i < 4; ++i) {  // the 2x2 around the point: bilinear, with the surface check
        ivec2 tap = ivec2(base) + ivec2(i & 1, i >> 1);
        bool inside = all(greaterThanEqual(tap, ivec2(0))) && all(lessThan(tap, size));
        float alike = inside ? distanceSimilarity(expected, texelFetch(historySurfaceDistance, tap, 0).r) : 0.0;
        sharp = sharp && alike >= 0.5;
        if (alike <= 0.0) continue;
        float b = ((i & 1) != 0 ? f.x : 1.0 - f.x) * ((i >> 1) != 0 ? f.y : 1.0 - f.y) * alike;
        float n;
        SkySample s = unpackSkyMedium(texelFetch(historySkyMedium, tap, 0), n);
        history.inscatter += b * s.inscatter;
        history.transmittance += b * s.transmittance;
        samples += b * n;
        weight += b;
        float l = luminance(s.transmittance * behind + s.inscatter);
        lo = min(lo, l);
        hi = max(hi, l);
    }
    contrast = !sharp ? 1.0 : hi > lo ? (hi - lo) / max(hi, 1.0e-6) : 0.0;
    if (sharp) {  // Catmull-Rom over the 4x4, the outer ring clamped to the frame's edge
        vec4 cx = vec4(f.x * (-0.5 + f.x * (1.0 - 0.5 * f.x)), 1.0 + f.x * f.x * (-2.5 + 1.5 * f.x),
                       f.x * (0.5 + f.x * (2.0 - 1.5 * f.x)), f.x * f.x * (-0.5 + 0.5 * f.x));
        vec4 cy = vec4(f.y * (-0.5 + f.y * (1.0 - 0.5 * f.y)), 1.0 + f.y * f.y * (-2.5 + 1.5 * f.y),
                       f.y * (0.5 + f.y * (2.0 - 1.5 * f.y)), f.y * f.y * (-0.5 + 0.5 * f.y));
        SkySample cubic = SkySample(vec3(0.0), vec3(0.0));
        float cubicSamples = 0.0;
        for (int j = 0; j < 4; ++j) {
            for (int i = 0; i < 4; ++i) {
                ivec2 tap = clamp(ivec2(base) + ivec2(i - 1, j - 1), ivec2(0), size - 1);
                float c = cx[i] * cy[j];
                float n;
                SkySample s = unpackSkyMedium(texelFetch(historySkyMedium, tap, 0), n);
                cubic.inscatter += c * s.inscatter;
                cubic.transmittance += c * s.transmittance;
                cubicSamples += c * n;
            }
        }
        history = SkySample(max(cubic.inscatter, vec3(0.0)), clamp(cubic.transmittance, vec3(0.0), vec3(1.0)));
        samples = cubicSamples;
        weight = 1.0;
    } else if (weight > 0.0) {
        history.inscatter /= weight;
        history.transmittance /= weight;
        samples /= weight;
    }
}

// How far the anti-aliasing's sub-pixel jitter moved between the frames (the explorer's: every
// frame), in pixels: a point that stood still lies that far off its pixel's centre in the
// previous frame's image.
vec2 jitterShift() { return vec2(frame.previousJitterX, frame.previousJitterY) - frame.jitter; }

// How far the history's texels lie off the pixels they are read for. Where the camera and the
// sun stood (only the clock ran, or nothing), none: each texel is taken for its own pixel, a
// sample of the pixel's area at the jitter it was traced with, as the pixel's new samples are
// (at another jitter at each visit: subPixelJitter), so the history is neither resampled
// between texels (blurred) every frame nor taken for moving, which marks every edge and line
// for the full-rate march (tests/test_temporal.cpp, WithTheExplorersAntiAliasing...). Else the
// jitter's shift: the history is read where the point was.
vec2 historyJitterShift() { return frame.viewStillSincePrevious > 0.5 ? vec2(0.0) : jitterShift(); }

// Where the history holds the point of the ray `dir` (pixels, centres at +0.5): where the
// previous frame saw it, less the jitter's shift where the view stood (historyJitterShift). The
// point: the clouds' opacity-weighted distance moved back by the wind where they dominate
// (`cloudy`), else the surface's, else (0 km) the direction alone.
vec2 previousPixel(vec3 dir, float reprojectionKm, bool cloudy) {
    vec3 previousNdc;
    if (reprojectionKm <= 0.0)
        previousNdc = previousNdcFromDirection(dir);
    else if (cloudy)
        previousNdc = previousNdcFromWorld(dir * (reprojectionKm * M_PER_KM) - frame.cloudDriftSincePrevious);
    else
        previousNdc = previousNdcFromWorld(dir * (reprojectionKm * M_PER_KM));
    vec2 jitterTakenOut = frame.viewStillSincePrevious > 0.5 ? jitterShift() : vec2(0.0);  // historyJitterShift
    return (previousNdc.xy * 0.5 + 0.5) * frame.viewportSize - jitterTakenOut;
}

// The distance the previous camera had to the surface point `distanceM` along `dir` (0: sky).
float previousSurfaceDistance(vec3 dir, float distanceM) {
    return distanceM > 0.0 ? length(dir * distanceM + frame.cameraFromPrevious) : 0.0;
}
