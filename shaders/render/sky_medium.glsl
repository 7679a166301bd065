// What the sky passes keep of the medium between the camera and the surface at each pixel, for
// the temporal march's history (render/sky_temporal.frag): its transmittance T and inscattered
// radiance S (Elek Eq. 19-20), and how many samples the temporal march has averaged into them.
// Packed as half floats into one RGBA32UI texel, so that the reconstruction reads a pixel's T
// and S at once: its Catmull-Rom read of the history takes 16 texel reads instead of 32 (on
// llvmpipe, from orbit at 480x270, with the samples' distance and error read together
// (render/sky_sparse.frag), the reconstruction went from 18.7 to 15.6 ms; docs/PERFORMANCE.md).
// Half floats are what the two RGBA16F textures held before: S is clamped to MAX_HDR_RADIANCE
// (atmosphere/interface.glsl), below the largest half float.
struct SkySample {
    vec3 inscatter;      // S
    vec3 transmittance;  // T
};

uvec4 packSkyMedium(SkySample s, float samples) {
    return uvec4(packHalf2x16(s.inscatter.rg), packHalf2x16(vec2(s.inscatter.b, samples)),
                 packHalf2x16(s.transmittance.rg), packHalf2x16(vec2(s.transmittance.b, 0.0)));
}

SkySample unpackSkyMedium(uvec4 texel, out float samples) {
    vec2 sb = unpackHalf2x16(texel.y);
    samples = sb.y;
    return SkySample(vec3(unpackHalf2x16(texel.x), sb.x), vec3(unpackHalf2x16(texel.z), unpackHalf2x16(texel.w).x));
}

// A pixel's running mean holds up to 16 samples (render/sky_temporal.frag); space is exact at once.
const float MAX_HISTORY_SAMPLES = 15.0;

// Space, where a ray misses the air (render/sky_temporal.frag's first branch, and render/
// sky_space.frag around the air's rectangle): no surface, T = 1 and S = 0 exactly, so L = the
// sun's disc (Elek §4.2.2) along the pixel centre's ray, as render/sky.frag forms it (an
// interpolated NDC differs in the last bit, and so may a pixel at the disc's edge).
vec3 spaceRadiance(vec2 fragCoord) {
#if NO_SUN_DISC
    return vec3(0.0);  // off the disc's rectangle (render/sky_air.glsl, behindTheAir)
#else
    return SunDiscRadiance(worldRayFromNdc(pixelCentreNdc(fragCoord)), frame.sunDirection);
#endif
}
uvec4 spaceSkyMedium() { return packSkyMedium(SkySample(vec3(0.0), vec3(1.0)), MAX_HISTORY_SAMPLES); }
