// The per-frame uniform block every pass reads; mirror of src/render/frame_uniforms.h
// (std140: each vec3 is followed by one float that fills its 16 bytes).
#include "common/bindings.glsl"

layout(std140, binding = BLOCK_FRAME) uniform FrameBlock {
    mat4 clipFromView;           // reversed-Z, infinite far plane
    mat4 viewFromClip;
    mat4 viewFromWorld;          // rotation only: world axes, camera at the origin
    mat4 worldFromView;          // rotation only
    mat4 previousClipFromWorld;  // the previous frame's clipFromView * viewFromWorld (its camera at the origin)
    vec3 planetCenterFromCamera; // m, world axes, formed in double
    float planetRadius;          // m
    vec3 cameraUp;               // radial unit up at the camera
    float cameraAltitude;        // m above the planet radius, formed in double
    vec3 sunDirection;           // unit, towards the sun
    float time;                  // s: the scene's clock (waves, wind)
    vec3 cameraFromPrevious;     // m: this frame's camera - the previous frame's, formed in double
    float historyValid;          // 1 when the previous frame's targets may be reprojected, else 0
    vec2 viewportSize;           // pixels
    vec2 inverseViewportSize;
    vec2 jitter;                 // sub-pixel offset of this frame's sample (Halton 2, 3), pixels in [-0.5, 0.5]
    float nearPlane;             // m
    float exposure;              // tone mapping: display = 1 - exp(-exposure * radiance)
    int frameIndex;              // frames since the renderer started
    float cameraDepthBelowSea;   // m below the mean sea surface (> 0: the camera is under water)
    float stillSincePrevious;    // 1: the camera, the sun and the clock are the previous frame's (nothing moved but the
                                 // anti-aliasing's sub-pixel jitter, maybe)
    float previousJitterX;       // pixels: the previous frame's jitter (its clipFromView's offset), x ...
    vec3 cloudDriftSincePrevious; // m, world axes: how far the wind moved the clouds since the previous frame
    float previousJitterY;       // ... and y
    float temporalRefineError;   // render.temporal_refine_error (render/sky_temporal.frag)
    float viewStillSincePrevious; // 1: the camera and the sun are the previous frame's (the clock and the jitter may have moved on)
    // The view's side planes (x = -w, x = w, y = -w, y = w of its clip space), camera-relative world
    // axes, formed in double on the CPU: dot(p.xyz, xyz) + w is how far (m) p lies inside each.
    vec4 viewSidePlanes[4];
} frame;

// World-oriented direction of the view ray through a point in NDC (x, y in [-1, 1]).
// The NDC of a pixel's centre (pixels, as gl_FragCoord.xy: +0.5): the sky passes that march a
// pixel form its ray from this, in fragment and compute shaders alike, so that a pixel marched
// again by render/sky_refine.comp is the full-rate pass's to the bit (an interpolated NDC
// differs from it by rounding, and a march's step decisions can turn on that).
vec2 pixelCentreNdc(vec2 centre) { return centre * frame.inverseViewportSize * 2.0 - 1.0; }

vec3 worldRayFromNdc(vec2 ndc) {
    vec4 view = frame.viewFromClip * vec4(ndc, 0.5, 1.0);
    return normalize(mat3(frame.worldFromView) * (view.xyz / view.w));
}

// The unit view ray (world axes) through the centre of `pixel`.
vec3 pixelRay(ivec2 pixel) { return worldRayFromNdc(pixelCentreNdc(vec2(pixel) + 0.5)); }

const float M_PER_KM = 1000.0;

// The camera relative to the planet centre in km (the atmosphere model's unit), from the
// radial up and the altitude formed in double on the CPU.
vec3 cameraFromPlanetCentreKm() { return frame.cameraUp * ((frame.planetRadius + frame.cameraAltitude) / M_PER_KM); }

// How much farther from the planet centre than the camera a point (m, relative to the camera,
// world axes) lies, m: |C + p| - |C| = (2 C.p + p.p) / (|C + p| + |C|), which subtracts
// nothing of planet size.
float riseFromCameraM(vec3 pointFromCamera) {
    vec3 c = -frame.planetCenterFromCamera;
    return (2.0 * dot(c, pointFromCamera) + dot(pointFromCamera, pointFromCamera)) /
           (length(c + pointFromCamera) + length(c));
}

// How far a point (m, relative to the camera, world axes) lies below the mean sea surface, m
// (< 0 above it): the camera's depth less the point's rise.
float depthBelowSeaM(vec3 pointFromCamera) { return frame.cameraDepthBelowSea - riseFromCameraM(pointFromCamera); }

// The frame's height in pixels (the render targets' own, as src/render/render_targets.cpp sizes them).
int frameHeightPixels() { return int(round(1.0 / frame.inverseViewportSize.y)); }

// Angle one pixel subtends vertically, rad (from the vertical field of view).
float radiansPerPixel() { return 2.0 * atan(1.0 / frame.clipFromView[1][1]) * frame.inverseViewportSize.y; }

// How far a mesh drawn with triangle edges of `edgePixels` on screen sags below the sphere it
// approximates between its vertices at `distanceM` from the camera, m: its chords are
// (edge length)^2 / 8r below the sphere (a kilometre from space; nothing near the camera).
float meshSagM(float distanceM, float edgePixels) {
    float edge = distanceM * radiansPerPixel() * edgePixels;
    return edge * edge / (8.0 * frame.planetRadius);
}

// Reversed-Z infinite projection: depth = near / distance along the view axis.
float depthFromViewDistance(float viewDistance) { return frame.nearPlane / viewDistance; }
float viewDistanceFromDepth(float depth) { return frame.nearPlane / depth; }

// Where a point (m, relative to this frame's camera, world axes) was in the previous
// frame's NDC: the offset between the cameras comes formed in double, so nothing of planet
// size is subtracted here. Meaningful only where frame.historyValid is 1.
vec3 previousNdcFromWorld(vec3 pointFromCamera) {
    vec4 clip = frame.previousClipFromWorld * vec4(pointFromCamera + frame.cameraFromPrevious, 1.0);
    return clip.xyz / clip.w;
}

// Where a direction at infinity (world axes) was in the previous frame's NDC; w <= 0 (behind
// the previous camera) gives a point far outside [-1, 1]. Meaningful only where
// frame.historyValid is 1.
vec3 previousNdcFromDirection(vec3 dir) {
    vec4 clip = frame.previousClipFromWorld * vec4(dir, 0.0);
    return clip.w > 0.0 ? clip.xyz / clip.w : vec3(1.0e9);
}
