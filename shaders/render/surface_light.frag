// Surface light: G-buffer -> the radiance leaving each surface point towards the camera,
// with no air in it (the sky pass adds what lies between the camera and the point).
//
//   R_G = albedo / pi * (sun through the atmosphere * visibility + sky irradiance)
//                                                          (Elek Eq. 17, 20; Sperlhofer Eq. 2-13)
// Below the sea surface both are first dimmed by the water above the point (ocean/water.glsl),
// how deep from the height field's height (the G-buffer normal's w), not from the mesh's
// point: from afar the mesh's chords sag hundreds of metres below the sphere between its
// vertices, and coastal land lit as sea floor that deep showed as blue-grey combs and dashes
// along every coast.
// The ground's detail normals, filtered by the pixel's footprint, come with the spread of
// slopes the filter removed (the G-buffer material's b): the sun lights them with the
// expected clamped cosine over that spread (terrain/rough_cosine.glsl), so a far pixel gets
// the mean of what a close view of its facets shows (LEAN / Toksvig in spirit, issue 13).
// Also writes the distance along the view ray to the point, which the sky pass and the
// ocean read. Pixels where nothing was drawn keep the cleared 0 (no surface).
#include "common/frame_uniforms.glsl"
#include "common/gbuffer.glsl"
#define SUN_VISIBILITY_TERRAIN 1  // the terrain's shadows in the sun (terrain/terrain_shadow.glsl)
#include "atmosphere/interface.glsl"
#include "ocean/water.glsl"
#include "terrain/rough_cosine.glsl"

in vec2 vNdc;
layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D gNormal;
layout(binding = UNIT_GBUFFER_ALBEDO) uniform sampler2D gAlbedo;
layout(binding = UNIT_GBUFFER_MATERIAL) uniform sampler2D gMaterial;
layout(binding = UNIT_GBUFFER_DEPTH) uniform sampler2D gDepth;

layout(location = 0) out vec4 outSurfaceRadiance;
layout(location = 1) out float outSurfaceDistance;

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

// A normal whose clamped cosine with the sun is the expected one over facets whose slopes
// spread by `slopeSpread` (per component) about `normal`: turned towards or away from the sun
// in the plane of the two. The spread of n.l is the slopes' projected on the sun's direction
// within the surface, slopeSpread * sqrt(1 - mu^2).
vec3 shadingNormal(vec3 normal, vec3 sun, float slopeSpread) {
    float mu = dot(normal, sun);
    vec3 across = normal - mu * sun;
    float acrossLength = length(across);
    if (slopeSpread <= 0.0 || acrossLength < 1.0e-4) return normal;
    float cosine = expectedClampedCosine(mu, slopeSpread * sqrt(max(1.0 - mu * mu, 0.0)));
    return cosine * sun + sqrt(max(1.0 - cosine * cosine, 0.0)) * (across / acrossLength);
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(gDepth, pixel, 0).r;
    if (depth <= 0.0) discard;  // reversed-Z 0: nothing drawn, the sky pass shows the sky here

    vec3 dir = worldRayFromNdc(vNdc);
    vec3 forward = -vec3(frame.worldFromView[2]);
    float rayDistance = viewDistanceFromDepth(depth) / max(dot(dir, forward), 1e-6);  // m
    vec4 normalAndHeight = texelFetch(gNormal, pixel, 0);
    rayDistance = onTheHeightField(dir, rayDistance, normalAndHeight.w);
    vec3 point = cameraFromPlanetCentreKm() + dir * (rayDistance / M_PER_KM);

    vec3 normal = normalize(normalAndHeight.xyz);
    vec3 albedo = texelFetch(gAlbedo, pixel, 0).rgb;
    vec3 up = normalize(point);
    vec3 shading = shadingNormal(normal, frame.sunDirection, texelFetch(gMaterial, pixel, 0).b);
    vec3 skyIrradiance;
    vec3 sunIrradiance = SunAndSkyIrradiance(point, shading, frame.sunDirection, skyIrradiance);
    // The sky's share is linear in the normal's rise, (1 + n.up) / 2 (Bruneton's
    // GetSunAndSkyIrradiance): the mean normal's, not the shading normal's.
    skyIrradiance *= (1.0 + dot(normal, up)) / max(1.0 + dot(shading, up), 1.0e-3);
    // The sea level less the ground's height: the camera's depth below the sea plus its
    // altitude is the sea level (both formed in double; a dry world's depth is -1e30).
    float depthBelowSea = frame.cameraDepthBelowSea + frame.cameraAltitude - normalAndHeight.w;
    lightUnderWater(depthBelowSea, dot(up, frame.sunDirection), sunIrradiance, skyIrradiance);
    outSurfaceRadiance = vec4(albedo / PI * (sunIrradiance + skyIrradiance), 1.0);
    outSurfaceDistance = rayDistance;
}
