// The cloud layer's density at a point and the sun's transmittance through it, for every
// pass that draws (the surfaces' shadows come from here through the atmosphere
// interface's SunVisibility). Needs cloud_model.glsl and cloud_block.glsl. Positions in
// km from the planet centre.
//
// Written in the subset of GLSL that is also C++ (Number / Length, single components, no
// swizzles), so that src/clouds/cloud_reference.h compiles this very text in double, with
// CPU samplers for the volume and the weather map, as the CPU reference of the march.

// CLOUD_FAR_FIELD_ONLY 1: the CPU found that every footprint this frame sees the clouds with is
// the far field's alone (src/clouds/cloud_block.h, seenInFarFieldOnly: the camera far above the
// layer and the highest ground, from space), so the volume is never read and the sun's way
// through the layer is the closed form. A program rather than a branch (src/render/
// atmosphere_program.h): a software renderer runs the volume's code and the sun samples' first
// turn for every pixel, masked, even where no pixel takes them.
#ifndef CLOUD_FAR_FIELD_ONLY
#define CLOUD_FAR_FIELD_ONLY 0
#endif
// CLOUDS_OFF 1: the CPU found no cloud layer in this frame (the block's `enabled` 0: the preset's
// clouds off, no coverage or density, no volume), so no code that reads the clouds is built: the
// sun's way through the layer is clear and the view ray crosses no layer (clouds/cloud_march.glsl).
// What `enabled` 0 gives, exactly, without a software renderer running the layer's code for every
// pixel, masked, behind the test of `enabled` (the clear sky pass at `orbit`: about half its cost).
#ifndef CLOUDS_OFF
#define CLOUDS_OFF 0
#endif

// How far the far field has taken over (0: the volume alone, 1: the far field alone) for a
// pixel footprint of `footprintKm`: from 2 to 8 voxels, where trilinear sampling starts to
// alias and where it would be only noise.
Number CloudFarBlend(Length footprintKm) {
#if CLOUD_FAR_FIELD_ONLY
    return 1.0;
#else
    return smoothstep(2.0 * clouds.voxelKm, 8.0 * clouds.voxelKm, footprintKm);
#endif
}

// The volume's mip level for a pixel footprint of `footprintKm`: level 0 up to a voxel, one
// more per doubling (a texel of level 3 spans the 8 voxels where the far field has taken over),
// so a pixel that spans voxels reads their mean rather than one of them; 0 without the far
// field (the volume as it is, for reference frames).
Number CloudVolumeLod(Length footprintKm) {
    if (clouds.voxelKm > 1.0e20) return 0.0;
    return min(log2(max(footprintKm / clouds.voxelKm, 1.0)), 3.0);
}

// How far from `point` (km, along any straight way through the layer) no cloud lies for sure, where
// the weather map's coverage there is `mapCoverage`: 0 where that is not 0; else the clear sky map's
// angle there (src/clouds/clear_sky.h: the map's coverage is 0 within it) as the chord it allows
// between two points of the layer (at least bottomRadius from the centre, so a chord d spans at most
// 2 asin(d / (2 bottomRadius))). 0 too where the map says nothing: a layer of constant density, or
// coverage over 1/2 (CloudLocalCoverage then lifts a 0). Read only where the weather has no
// coverage: a software renderer skips the read when no pixel of a group takes it, so a march in
// cloud does not pay for it (the `cumulus` view's march: 3 to 9 % dearer with a read at every step).
Length CloudClearDistance(vec3 direction, Number mapCoverage) {
    if (mapCoverage > 0.0 || clouds.coverage > 0.5 || clouds.constantDensity != 0) return 0.0;
    return clouds.bottomRadius * textureLod(clearSky, direction, 0.0).x;  // (the texture holds 2 sin(angle / 2))
}

// Density at `point` (Michelic Eq. 12-14), seen with a pixel footprint of `footprintKm`:
// < 0 where the volume says the zero-density border is around (a large step is safe), else
// >= 0. Where the footprint spans voxels, blended into the far field (cloud_model.glsl).
// `clearKm`: how far no cloud lies for sure (CloudClearDistance): where the weather is read and has no
// coverage, and where the volume's border answers first (no weather read) if `weatherClear` says the
// last sample's weather had none; that is set to whether this one's has none, where it is read. (A
// read of the clear sky in every border made the march in cloud 6 % dearer, `cumulus`; without
// one there, the `ground` view's 40 ms march took 59: a border's short step before each long one.)
Number CloudDensityAndClearAt(vec3 point, Length footprintKm, INOUT(bool) weatherClear, OUT(Length) clearKm) {
    clearKm = 0.0;
    Length r = length(point);
    if (r < clouds.bottomRadius || r > clouds.topRadius) return -1.0;
#if !CLOUD_FAR_FIELD_ONLY  // (only ever built for a layer that is not of constant density)
    if (clouds.constantDensity != 0) return clouds.densityScale;
#endif
    Number far = CloudFarBlend(footprintKm);
    // Eq. 12, camera-relative: the tile offset of the camera comes formed in double and
    // GL_REPEAT takes the fract.
    Number value = 0.0;
    if (far < 1.0) {
        vec3 c = (clouds.cameraTileOffset + (point - clouds.cameraFromCentre)) / clouds.tileWidth;
        value = textureLod(cloudVolume, c, CloudVolumeLod(footprintKm)).x;
        if (value < 0.0 && far == 0.0) {  // nothing within the border: the weather cannot add cloud
            if (weatherClear) clearKm = CloudClearDistance(point / r, 0.0);  // (the clear sky may reach further)
            return value;
        }
    }
    vec4 weatherTexel = textureLod(weatherMap, point / r, 0.0);
    vec2 weather = vec2(weatherTexel.x, weatherTexel.y);  // coverage, type
    clearKm = CloudClearDistance(point / r, weather.x);
    weatherClear = weather.x <= 0.0;
    Number coverage = CloudLocalCoverage(weather.x, clouds.coverage);
    Length depth = clouds.topRadius - clouds.bottomRadius;
    Number fraction = (r - clouds.bottomRadius) / depth;
    bool typed = clouds.typeProfiles != 0;
    Number h = typed ? CloudTypeHeightSignal(fraction, weather.y) : CloudHeightSignal(r, clouds.bottomRadius, clouds.topRadius);  // Eq. 13
    Number column = (2.0 / 3.0) * (typed ? CloudTypeProfileWidth(weather.y) : 1.0);
    Number farDensity = CloudFarFieldDensity(coverage, h, column, depth, clouds.extinction * clouds.densityScale);
#if CLOUD_FAR_FIELD_ONLY
    return farDensity * clouds.densityScale;
#else
    Number near = max(CloudDensityFromTextureAndCoverage(value, h, coverage), 0.0);  // Eq. 14
    return mix(near, farDensity, far) * clouds.densityScale;
#endif
}

// The density alone (the samples towards the sun).
Number CloudDensityAt(vec3 point, Length footprintKm) {
    bool weatherClear = false;
    Length clearKm;
    return CloudDensityAndClearAt(point, footprintKm, weatherClear, clearKm);
}

// A footprint that sees the far field alone (8 voxels), for a caller that wants no volume
// detail (the sea's reflection); 0 where there is no far field (switched off, no volume).
Length CloudFarFieldFootprint() { return clouds.voxelKm < 1.0e20 ? 8.0 * clouds.voxelKm : 0.0; }

// The footprint of a pixel at `point`: its distance from the camera times the angle a
// pixel spans.
Length CloudFootprintAt(vec3 point) { return length(point - clouds.cameraFromCentre) * clouds.pixelAngle; }

// The far field's optical depth per unit extinction from `a` to `b` (in the layer, `way` km
// apart), in closed form (cloud_model.glsl's CloudFarFieldPath): the weather at the
// middle of the way, the heights of its ends. What the samples would approximate, exactly.
Length CloudFarFieldPathToSun(vec3 a, vec3 b, Length way) {
    vec3 middle = 0.5 * (a + b);
    vec4 weatherTexel = textureLod(weatherMap, middle / length(middle), 0.0);
    Number coverage = CloudLocalCoverage(weatherTexel.x, clouds.coverage);
    Length depth = clouds.topRadius - clouds.bottomRadius;
    Number bottom = 0.0;
    Number top = 1.0;
    if (clouds.typeProfiles != 0) CloudTypeBounds(weatherTexel.y, bottom, top);
    Number span = top - bottom;
    Number ua = ((length(a) - clouds.bottomRadius) / depth - bottom) / span;
    Number ub = ((length(b) - clouds.bottomRadius) / depth - bottom) / span;
    return CloudFarFieldPath(coverage, span, ua, ub, way, depth, clouds.extinction);
}

// Whether no cloud lies for sure within `way` km of `start` (a point of the layer): the clear sky
// there (CloudClearDistance, from the weather map's coverage at it) reaches that far.
bool CloudClearAlong(vec3 start, Length way) {
    vec3 direction = start / length(start);
    return CloudClearDistance(direction, textureLod(weatherMap, direction, 0.0).x) >= way;
}

// Optical depth per unit extinction (the integral of the density, km) from `point` towards
// the sun: `samples` density samples spread over the sun ray's way through the
// layer, or over `maxLength` km of it where that way is longer, seen with a footprint of
// `footprintKm` (the view sample's); in closed form where that footprint sees the far field
// alone. 0 without clouds. `clearSkyCheck`: none of the samples where the clear sky at the way's
// start covers the whole way (CloudClearAlong: every sample lies within the way's length of it),
// where they would all read 0; for the surfaces' shadows (under the `ground` view's clear sky, a
// third of the surface light's time), not for a cloud's own samples (CloudSource), which lie in
// cloud: the check's weather read there made the march in cloud 8 to 15 % dearer.
Length CloudDensityPathToSun(vec3 point, vec3 sun, Length maxLength, Length footprintKm, int samples,
                             bool clearSkyCheck) {
#if CLOUDS_OFF
    return 0.0;
#else
    if (clouds.enabled == 0) return 0.0;
    Length r = length(point);
    vec2 first;
    vec2 second;
    int count = CloudLayerIntervals(r, dot(point, sun) / r, 1.0e9, clouds.bottomRadius, clouds.topRadius, first, second);
    if (count == 0) return 0.0;
    Length way = min(first.y - first.x, maxLength);
#if CLOUD_FAR_FIELD_ONLY
    return CloudFarFieldPathToSun(point + sun * first.x, point + sun * (first.x + way), way);
#else
    if (CloudFarBlend(footprintKm) >= 1.0 && clouds.constantDensity == 0)
        return CloudFarFieldPathToSun(point + sun * first.x, point + sun * (first.x + way), way);
    int taken = clearSkyCheck && CloudClearAlong(point + sun * first.x, way) ? 0 : samples;
    Length step = way / Number(max(samples, 1));
    Length path = 0.0;
    for (int i = 0; i < taken; ++i)
        path += max(CloudDensityAt(point + sun * (first.x + (Number(i) + 0.5) * step), footprintKm), 0.0) * step;
    return path;
#endif
#endif  // CLOUDS_OFF
}

// The clouds' transmittance towards the sun (Michelic Eq. 15 along the sun ray: T_sun)
// from a point the camera sees (the surfaces' shadows): with that point's footprint, so a
// shadow seen from orbit is the far field's, not speckle.
Number CloudSunTransmittance(vec3 point, vec3 sun, Length maxLength) {
    return exp(-clouds.extinction *
               CloudDensityPathToSun(point, sun, maxLength, CloudFootprintAt(point), clouds.sunSamples, true));
}
