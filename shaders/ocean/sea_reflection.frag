// The clouds in the sea's reflection: the samples' program, and with SEA_REFLECTION_COMPOSE
// their spread to every pixel (ocean/sea_reflection.glsl says how); with
// SEA_REFLECTION_LIST_ALL the compose lists every pixel to be marched on its own (the
// per-pixel march, to compare with: Renderer::setSeaReflectionSamples).
#include "ocean/sea_reflection.glsl"
#include "render/block_samples.glsl"

#ifndef SEA_REFLECTION_COMPOSE
#define SEA_REFLECTION_COMPOSE 0
#endif
#ifndef SEA_REFLECTION_LIST_ALL
#define SEA_REFLECTION_LIST_ALL 0
#endif

layout(binding = UNIT_SEA_REFLECTION_SAMPLES) uniform sampler2D seaReflectionSamples;

layout(location = 0) out vec4 outRadiance;

void main() {
#if SEA_REFLECTION_COMPOSE || SEA_REFLECTION_LIST_ALL
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 own = texelFetch(seaReflection, pixel, 0);
    if (own.w <= 0.0) discard;
    vec3 crossing = layerCrossing(seaPointAt(pixel), normalize(own.xyz));
    ivec2 corners[4];
    blockSampleCorners(pixel, SEA_REFLECTION_SPACING, textureSize(seaReflectionSamples, 0) - 1, corners);
    vec3 sum = vec3(0.0);
    float total = 0.0;
    for (int i = 0; i < 4; ++i) {  // a corner counted twice (a pixel in a row or column of samples) weighs twice
        vec4 change = texelFetch(seaReflectionSamples, corners[i], 0);
        ivec2 at = corners[i] * SEA_REFLECTION_SPACING;
        vec3 theirs = layerCrossing(seaPointAt(at), normalize(texelFetch(seaReflection, at, 0).xyz + 1.0e-9));
        float w = change.a * max(1.0 - distance(theirs, crossing) / SEA_REFLECTION_CROSSING_SPREAD_KM, 0.0);
        sum += w * change.rgb;
        total += w;
    }
    if (SEA_REFLECTION_LIST_ALL != 0) total = 0.0;
    if (total < SEA_REFLECTION_MIN_WEIGHT) {  // marched on its own (ocean/sea_reflection.comp)
        listPixel(pixel);
        discard;
    }
    outRadiance = vec4(own.w * sum / total, 0.0);
#else
    outRadiance = cloudChangeAt(ivec2(gl_FragCoord.xy) * SEA_REFLECTION_SPACING);
#endif
}
