// Per-frame uniform block; mirror of src/render/frame_uniforms.h (std140).
layout(std140, binding = 0) uniform FrameUniforms {
    mat4 clipFromView;
    mat4 viewFromClip;
    mat4 viewFromWorld;
    mat4 worldFromView;
    vec4 planetCenterFromCamera;  // xyz: centre - camera (m); w: planet radius (m)
    vec4 cameraUp;                // xyz: radial up at the camera; w: camera altitude (m)
    vec4 sunDirection;            // xyz: towards the sun; w: angular radius (rad)
    vec4 viewport;                // w, h, 1/w, 1/h
    vec4 camera;                  // x: near plane (m); y: exposure
} frame;

// World-oriented direction of the view ray through a point in NDC (x, y in [-1, 1]).
vec3 worldRayFromNdc(vec2 ndc) {
    vec4 view = frame.viewFromClip * vec4(ndc, 0.5, 1.0);
    return normalize(mat3(frame.worldFromView) * (view.xyz / view.w));
}

const float M_PER_KM = 1000.0;

// The camera relative to the planet centre in km (the atmosphere model's unit), from the
// radial up and the altitude formed in double on the CPU.
vec3 cameraFromPlanetCentreKm() {
    return frame.cameraUp.xyz * ((frame.planetCenterFromCamera.w + frame.cameraUp.w) / M_PER_KM);
}

// Angle one pixel subtends vertically, rad (from the vertical field of view).
float radiansPerPixel() { return 2.0 * atan(1.0 / frame.clipFromView[1][1]) * frame.viewport.w; }

// Reversed-Z infinite projection: depth = near / distance along the view axis.
float depthFromViewDistance(float viewDistance) { return frame.camera.x / viewDistance; }
float viewDistanceFromDepth(float depth) { return frame.camera.x / depth; }
