// Terrain into the G-buffer: per-pixel normal from the height field's analytic
// gradient (independent of tessellation), material by height, slope and
// latitude (terrain/height.glsl), albedo per material.
#include "common/frame_uniforms.glsl"
#include "common/constants.glsl"
#include "common/gbuffer.glsl"
#include "noise/simplex.glsl"
#include "terrain/height.glsl"

in vec3 teDirection;
in float teHeight;

#include "terrain/terrain_block.glsl"

layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec4 outAlbedo;
layout(location = 2) out vec4 outMaterial;

// Linear albedo per material id (sea floor, rock, snow, sand; grass comes from the preset).
const vec3 MATERIAL_ALBEDO[TERRAIN_MATERIAL_COUNT] =
    vec3[](vec3(0.10, 0.09, 0.07), vec3(0.13, 0.11, 0.09), vec3(0.80, 0.82, 0.86), vec3(0.36, 0.31, 0.21),
           vec3(0.0));  // grass: terrainLowlandAlbedo

// The lowlands take the preset's albedo; so do a dry world's basins, a little darker.
vec3 materialAlbedo(int material) {
    if (material == TERRAIN_MATERIAL_GRASS) return terrainLowlandAlbedo;
    if (material == TERRAIN_MATERIAL_SEA_FLOOR && terrainHasOcean == 0) return 0.7 * terrainLowlandAlbedo;
    return MATERIAL_ALBEDO[material];
}

void main() {
    vec3 up = normalize(teDirection);
    vec3 normal = terrainNormal(up, terrainShape, uContinents, frame.planetRadius);
    float slope = terrainSlope(normal, up);
    float latitude = terrainLatitude(up);
    vec3 albedo = vec3(0.0);
    for (int m = 0; m < TERRAIN_MATERIAL_COUNT; ++m)
        albedo += terrainMaterialWeight(m, teHeight, slope, latitude) * materialAlbedo(m);
    outNormal = vec4(normal, 0.0);
    outAlbedo = vec4(albedo, 1.0);
    outMaterial = vec4(float(MATERIAL_GROUND) / 255.0, 1.0, 0.0, 0.0);
}
