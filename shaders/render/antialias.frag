// Temporal anti-aliasing of the explorer's frames (Renderer::setTemporalAntialiasing): each
// frame is rendered with its projection moved by a sub-pixel offset (Halton 2, 3 over 16
// frames: frame_uniforms.h subPixelJitter), and this pass blends it into the history of the
// previous results, so that a still camera sees the mean over the pixel's area, as a still
// rendered with `--samples` does, and edges (the planet's limb, ridges, coastlines) are
// anti-aliased. Chosen over a spatial filter (FXAA, SMAA) because the frame already keeps a
// history with its camera in double and a jitter (the frame issue), and because it also
// averages what a spatial filter cannot see: sub-pixel features and the noise of the march.
//
// The history is reprojected through the pixel's surface point (its distance along the ray:
// render targets' surfaceDistance) or, for the sky, its direction, into the previous frame,
// and read at the point's unjittered position there (the history holds the mean of many
// jitters: the unjittered image). It is clipped to the box of this frame's 3x3 samples
// (mean +- 1.25 standard deviations, in YCoCg, Salvi's variance clipping) so that what
// moved or changed does not ghost, and blended with this frame's sample by
// TAA_CURRENT_WEIGHT: an exponential mean over about 1 / TAA_CURRENT_WEIGHT frames. A frame
// without history (a jump, a resize, a parameter change) is passed through unchanged.
#include "common/frame_uniforms.glsl"

layout(binding = UNIT_HDR_RADIANCE) uniform sampler2D uRadiance;          // this frame's, jittered
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D uSurfaceDistance;  // m, 0: no surface
layout(binding = UNIT_HISTORY_RADIANCE) uniform sampler2D uHistory;       // the previous result

out vec4 outRadiance;

const float TAA_CURRENT_WEIGHT = 0.1;
const float TAA_CLIP_SIGMAS = 1.25;

vec3 rgbToYCoCg(vec3 c) {
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}

vec3 yCoCgToRgb(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// The history at `pixel` (pixels, continuous) by Catmull-Rom over 4x4 texels in 5 bilinear
// fetches (Jimenez's approximation, the corners dropped): bilinear alone blurs the history a
// little every frame it is read between texels, which adds up while the camera moves.
vec3 historyCatmullRom(vec2 pixel) {
    vec2 centre = floor(pixel - 0.5) + 0.5;
    vec2 f = pixel - centre;
    vec2 w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
    vec2 w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
    vec2 w2 = f * (0.5 + f * (2.0 - 1.5 * f));
    vec2 w3 = f * f * (-0.5 + 0.5 * f);
    vec2 w12 = w1 + w2;
    vec2 at0 = (centre - 1.0) * frame.inverseViewportSize;
    vec2 at3 = (centre + 2.0) * frame.inverseViewportSize;
    vec2 at12 = (centre + w2 / w12) * frame.inverseViewportSize;
    vec3 sum = texture(uHistory, vec2(at12.x, at0.y)).rgb * (w12.x * w0.y) +
               texture(uHistory, vec2(at0.x, at12.y)).rgb * (w0.x * w12.y) +
               texture(uHistory, at12).rgb * (w12.x * w12.y) +
               texture(uHistory, vec2(at3.x, at12.y)).rgb * (w3.x * w12.y) +
               texture(uHistory, vec2(at12.x, at3.y)).rgb * (w12.x * w3.y);
    float weight = w12.x * w0.y + w0.x * w12.y + w12.x * w12.y + w3.x * w12.y + w12.x * w3.y;
    return max(sum / weight, vec3(0.0));
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 current = texelFetch(uRadiance, pixel, 0);
    if (frame.historyValid < 0.5) {
        outRadiance = current;
        return;
    }
    // Where the point at this pixel's centre (unjittered: the jitter moved the image by
    // frame.jitter, so the centre lies there in this frame) was in the previous frame,
    // unjittered, in pixels. The sample's own surface distance stands in for the centre's.
    vec2 ndc = (gl_FragCoord.xy + frame.jitter) * frame.inverseViewportSize * 2.0 - 1.0;
    vec3 ray = worldRayFromNdc(ndc);
    float distance = texelFetch(uSurfaceDistance, pixel, 0).r;
    vec3 previous = distance > 0.0 ? previousNdcFromWorld(ray * distance) : previousNdcFromDirection(ray);
    vec2 previousPixel = (previous.xy * 0.5 + 0.5) * frame.viewportSize - vec2(frame.previousJitterX, frame.previousJitterY);
    if (any(lessThan(previousPixel, vec2(0.0))) || any(greaterThan(previousPixel, frame.viewportSize))) {
        outRadiance = current;  // it was off screen
        return;
    }
    // This frame's neighbourhood: mean and spread, in YCoCg.
    vec3 mean = vec3(0.0);
    vec3 square = vec3(0.0);
    ivec2 last = ivec2(frame.viewportSize) - 1;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            vec3 c = rgbToYCoCg(texelFetch(uRadiance, clamp(pixel + ivec2(x, y), ivec2(0), last), 0).rgb);
            mean += c;
            square += c * c;
        }
    mean /= 9.0;
    vec3 sigma = sqrt(max(square / 9.0 - mean * mean, vec3(0.0)));
    vec3 history = rgbToYCoCg(historyCatmullRom(previousPixel));
    // Clip (not clamp) towards the mean: the history moves along the line to the box's centre.
    vec3 extent = TAA_CLIP_SIGMAS * sigma + 1.0e-7;
    vec3 offset = history - mean;
    vec3 units = abs(offset / extent);
    float outside = max(units.x, max(units.y, units.z));
    if (outside > 1.0) history = mean + offset / outside;
    vec3 blended = mix(yCoCgToRgb(history), current.rgb, TAA_CURRENT_WEIGHT);
    outRadiance = vec4(max(blended, vec3(0.0)), current.a);
}
