// The terrain reflected in the sea at the listed pixels (ocean/terrain_reflection.glsl): one
// invocation per pixel, dispatched indirectly (render/pixel_list.glsl).
#include "ocean/terrain_reflection.glsl"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;  // PIXEL_LIST_GROUP_SIZE
layout(binding = IMAGE_SURFACE_RADIANCE, rgba16f) uniform image2D surfaceRadiance;
layout(binding = IMAGE_SEA_REFLECTION, rgba32f) uniform image2D seaReflection;  // ray, weight (ocean/sea_light.frag)
layout(binding = UNIT_SEABED_DEPTH) uniform sampler2D seabedDepth;        // the G-buffer depth before the sea
layout(binding = UNIT_SEABED_RADIANCE) uniform sampler2D seabedRadiance;  // the surface radiance before the sea

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= pixelList.count) return;
    ivec2 pixel = listedPixel(i);
    vec4 sky = texelFetch(seaSkyReflection, pixel, 0);  // L_sky, the sea's distance along the view ray (m)
    vec4 mirror = imageLoad(seaReflection, pixel);      // the reflected ray, its weight w
    vec3 reflected = normalize(mirror.xyz);
    vec3 origin = pixelRay(pixel) * sky.a;  // m from the camera
    vec3 point = cameraFromPlanetCentreKm() + origin / M_PER_KM;               // km from the planet centre
    vec3 up = normalize(point);
    float reach = reachBelowLand(up, ocean.seaLevel, dot(reflected, up));
    ScreenReflection land = searchScreenReflection(origin, reflected, reach, pixel, seabedDepth, seabedRadiance);
    if (land.confidence <= 0.0) return;
    vec3 terrain = reflectedTerrainRadiance(land, point, reflected, frame.sunDirection);
    vec4 radiance = imageLoad(surfaceRadiance, pixel);
    radiance.rgb += mirror.w * land.confidence * (terrain - sky.rgb);
    imageStore(surfaceRadiance, pixel, vec4(clamp(radiance.rgb, vec3(0.0), vec3(MAX_HDR_RADIANCE)), radiance.a));
    imageStore(seaReflection, pixel, vec4(mirror.xyz, mirror.w * (1.0 - land.confidence)));
}
