// The clouds in the sea's reflection, marched at one pixel of each SEA_REFLECTION_SPACING-square
// block and spread to the pixels between (issue 15: marched in every sea pixel, the reflected
// march was half the ocean pass's cost at sea level). Three programs share this file:
//
//   ocean/sea_reflection.frag, samples: at the block's corner pixel, the clouds' change to what
//     the sea reflects there, dL_C = march - clear sky along the pixel's reflected ray (ocean/
//     cloud_reflection.glsl's CloudReflectionChange), from the ray and the point the ocean pass
//     left (its sea reflection target and the surface distance); a = 1 where it was marched, 0
//     where the pixel shows no sea that reflects the sky.
//   ocean/sea_reflection.frag with SEA_REFLECTION_COMPOSE: at every pixel the ocean shaded with
//     a weight w > 0 (coverage x Fresnel, less the share the terrain reflection pass gave to the
//     terrain), w times the samples' dL_C around it (the corners of its cell), each
//     weighted by how near its reflected ray is to the pixel's, added to the surface radiance
//     (additive blending). Where they weigh too little (the waves turned the pixel's ray away
//     from theirs, or a sliver of sea between land or sky samples), the pixel is listed
//     (render/pixel_list.glsl) ...
//   ocean/sea_reflection.comp: ... and marched on its own, one invocation per listed pixel.
//
// At the samples themselves, and at the listed pixels, the result is the per-pixel march's;
// between, dL_C of rays at most SEA_REFLECTION_RAY_SPREAD apart, which the reflected march
// (one slice per crossing of the layer, a 32nd of the sky's steps, the far field) resolves
// little of.
#include "common/frame_uniforms.glsl"
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/cloud_reflection.glsl"
#include "render/sample_spacing.glsl"
#define PIXEL_LIST_BINDING BUFFER_SEA_REFLECTION_LIST
#include "render/pixel_list.glsl"

layout(binding = UNIT_SEA_REFLECTION) uniform sampler2D seaReflection;      // ray, weight (ocean/sea_light.frag)
layout(binding = UNIT_SURFACE_DISTANCE) uniform sampler2D surfaceDistance;  // m along the view ray

// A sample's change is taken for a pixel in proportion to how near its reflected ray passes to
// the pixel's through the cloud layer (their crossings of the layer's middle): fully where they
// cross at one place, not at all this far apart (km). Where the four corner samples around (a
// corner counted as often as it is one: a pixel on a sample has it four times) weigh less than
// SEA_REFLECTION_MIN_WEIGHT together, of 4 at most, the pixel is marched on its own. Rays that leave the sea
// steeply cross close together; near the horizon a small turn moves the crossing by kilometres,
// and there the pixels march their own.
const float SEA_REFLECTION_CROSSING_SPREAD_KM = 1.0;
const float SEA_REFLECTION_MIN_WEIGHT = 0.5;

// The sea's point at `pixel`, km from the planet centre (the view ray to the surface distance).
vec3 seaPointAt(ivec2 pixel) {
    vec3 view = pixelRay(pixel);
    return cameraFromPlanetCentreKm() + view * (texelFetch(surfaceDistance, pixel, 0).r / M_PER_KM);
}

// Where the ray from `point` along the unit `ray` crosses the middle of the cloud layer (km from
// the planet centre): the sea lies below the layer, so every ray leaving it upwards crosses.
vec3 layerCrossing(vec3 point, vec3 ray) {
    float r = length(point);
    float middle = 0.5 * (clouds.bottomRadius + clouds.topRadius);
    float b = dot(point, ray);
    float t = -b + sqrt(max(b * b + (middle - r) * (middle + r), 0.0));
    return point + ray * t;
}

// dL_C at `pixel` (the ocean's ray and point there), a = 1; 0 where the ocean left no weight.
// A loop of one turn or none rather than an if: a software renderer runs both sides of an if,
// but skips a loop none of its pixels enters.
vec4 cloudChangeAt(ivec2 pixel) {
    vec4 ray = texelFetch(seaReflection, pixel, 0);
    vec4 change = vec4(0.0);
    for (int i = 0; i < (ray.w > 0.0 ? 1 : 0); ++i)
        change = vec4(CloudReflectionChange(seaPointAt(pixel), normalize(ray.xyz), frame.sunDirection), 1.0);
    return change;
}
