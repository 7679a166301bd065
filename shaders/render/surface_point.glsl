// The surface point a pixel of the G-buffer shows: the view ray through the pixel's centre,
// the distance along it (on the height field from afar) and the point, km from the planet
// centre. Read by the surface light and by the terrain shadow's samples
// (render/terrain_shadow.frag), which must find the very same point for a pixel.
// Include after common/frame_uniforms.glsl, with gNormal and gDepth declared.

// From afar, the distance along the ray to the height field rather than to the mesh: the
// terrain's chords sag below the sphere between vertices by (edge length)^2 / 8r (hundreds
// of metres from space), and a point that deep inside the ground ended the clouds' march
// below the cloud tops it should have stopped under (speckle and dashes over land wherever
// the terrain reaches into the cloud layer) and lit the ground from the wrong place. The
// mesh's point is moved along the ray by its altitude above the ground's height (the
// G-buffer's) over the rate the ray descends; near the camera, where the sag is far below a
// metre, nothing changes (the half-float height would add its own rounding there).
float onTheHeightField(vec3 dir, float meshDistance, float groundHeight) {
    float sag = meshSagM(meshDistance, 2.0 * terrainTargetEdgePixels);  // fractional tessellation: edges up to 2x
    float weight = smoothstep(1.0, 10.0, sag);
    if (weight <= 0.0) return meshDistance;
    vec3 fromCamera = dir * meshDistance;
    vec3 camera = -frame.planetCenterFromCamera;
    float meshAltitude = frame.cameraAltitude + riseFromCameraM(fromCamera);
    float descent = max(-dot(dir, normalize(camera + fromCamera)), 0.05);  // altitude lost per metre along the ray
    float limit = 2.0 * sag / descent + 50.0;
    return meshDistance + weight * clamp((meshAltitude - groundHeight) / descent, -limit, limit);
}

struct SurfacePoint {
    vec3 dir;              // unit view ray, world axes
    float rayDistance;     // m along it to the point
    vec3 point;            // km from the planet centre
    vec4 normalAndHeight;  // the G-buffer's normal (not normalised) and ground height, m
};

// False where nothing was drawn (reversed-Z depth 0: the sky pass shows the sky there).
bool surfacePointAt(ivec2 pixel, out SurfacePoint s) {
    float depth = texelFetch(gDepth, pixel, 0).r;
    s.dir = pixelRay(pixel);
    vec3 forward = -vec3(frame.worldFromView[2]);
    float meshDistance = viewDistanceFromDepth(max(depth, 1.0e-30)) / max(dot(s.dir, forward), 1e-6);  // m
    s.normalAndHeight = texelFetch(gNormal, pixel, 0);
    s.rayDistance = onTheHeightField(s.dir, meshDistance, s.normalAndHeight.w);
    s.point = cameraFromPlanetCentreKm() + s.dir * (s.rayDistance / M_PER_KM);
    return depth > 0.0;
}

// How far below the sea surface the point lies, m (< 0: above it): the camera's depth below the
// sea plus its altitude is the sea level (both formed in double; a dry world's depth is -1e30),
// less the ground's height.
// Of a ground height (the G-buffer normal's w), m: render/surface_marks.frag's test, the same expression.
float depthBelowSeaAt(float groundHeightM) { return frame.cameraDepthBelowSea + frame.cameraAltitude - groundHeightM; }
float depthBelowSea(SurfacePoint s) { return depthBelowSeaAt(s.normalAndHeight.w); }
