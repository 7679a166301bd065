// The cloud layer's parameters and baked textures as every pass sees them; mirror of
// src/clouds/cloud_block.h (std140). Lengths in km, coefficients per km at density 1.
#include "common/bindings.glsl"

layout(std140, binding = BLOCK_CLOUDS) uniform CloudBlock {
    vec3 cameraTileOffset;      // (camera + wind drift) modulo the tile, km, formed in double (Eq. 12)
    float tileWidth;            // w of Michelic Eq. 12, km
    vec3 cameraFromCentre;      // the camera from the planet centre, km (the same as the frame's)
    float bottomRadius;         // l_b, km from the planet centre
    float topRadius;            // l_t
    float coverage;             // [0, 1], the mean over the sphere (CloudLocalCoverage with the weather map's)
    float densityScale;
    float extinction;           // E
    float scattering;           // S
    float phaseGForward;
    float phaseGBack;
    float phaseBackWeight;
    float sunStep;              // km between the samples towards the sun
    float stepKm;               // march step inside clouds
    float largeStepKm;          // step through empty space: at most the volume's zero-density border
    float powder;               // 0: off
    int sunSamples;
    int maxSteps;
    int atmosphereSlices;       // per crossing of the layer (Eq. 17-18)
    int multipleScatteringOctaves;  // 1: single scattering
    int energyConservingStep;   // 1: Hillaire's step, 0: Eq. 16 as written
    int constantDensity;        // 1: uniform density densityScale in the layer
    int enabled;                // 0: no clouds (the march is the clear sky's)
    int typeProfiles;           // 1: the weather map's cloud type shapes the height signal
    float pixelAngle;           // rad a pixel spans (vertical fov / height): footprints for the far field
    float voxelKm;              // tileWidth / the volume's size; 1e30 without a volume or far field
    int statistics;             // 1: the sky pass counts its march steps (BUFFER_CLOUD_STATISTICS)
    float padding2;
} clouds;

layout(binding = UNIT_CLOUD_VOLUME) uniform sampler3D cloudVolume;   // tiling density, < 0: empty (border)
layout(binding = UNIT_WEATHER_MAP) uniform samplerCube weatherMap;   // r: coverage, g: cloud type
layout(binding = UNIT_CLEAR_SKY) uniform samplerCube clearSky;       // r: the chord 2 sin(a / 2) of the angle a around a
                                                                     // point with no coverage (nearest; src/clouds/clear_sky.h)
