// Placeholder planet: a ray-cast sphere written to the G-buffer exactly as the
// terrain pass will (normal, albedo, material, reversed-Z depth).
#include "common/frame_uniforms.glsl"
#include "common/constants.glsl"
#include "common/ray_sphere.glsl"

in vec2 vNdc;
uniform vec3 uAlbedo;

layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outMaterial;

void main() {
    vec3 dir = worldRayFromNdc(vNdc);
    float radius = frame.planetCenterFromCamera.w;
    float altitude = frame.cameraUp.w;
    vec3 up = frame.cameraUp.xyz;
    float t = raySphereNearestHit(altitude, radius, dot(dir, up));
    if (t < 0.0) discard;

    vec3 hitFromCamera = t * dir;
    // hit - centre, with the centre at -(R + h) up from the camera.
    vec3 normal = normalize(up * (radius + altitude) + hitFromCamera);
    float viewDistance = -(frame.viewFromWorld * vec4(hitFromCamera, 0.0)).z;
    gl_FragDepth = depthFromViewDistance(max(viewDistance, frame.camera.x));

    outNormal = vec4(normal, 0.0);
    outAlbedo = vec4(uAlbedo, 1.0);
    outMaterial = vec4(float(MATERIAL_GROUND) / 255.0, 1.0, 0.0, 0.0);
}
