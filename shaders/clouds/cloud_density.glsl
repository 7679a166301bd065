// The cloud layer's density at a point and the sun's transmittance through it, for every
// pass that draws (the surfaces' shadows come from here through the atmosphere
// interface's SunVisibility). Needs cloud_model.glsl and cloud_block.glsl. Positions in
// km from the planet centre.

// Density at `point` (Michelic Eq. 12-14): < 0 where the volume says the zero-density
// border is around (a large step is safe), else >= 0.
float CloudDensity(vec3 point) {
    float r = length(point);
    if (r < clouds.bottomRadius || r > clouds.topRadius) return -1.0;
    if (clouds.constantDensity != 0) return clouds.densityScale;
    // Eq. 12, camera-relative: the tile offset of the camera comes formed in double and
    // GL_REPEAT takes the fract.
    vec3 c = (clouds.cameraTileOffset + (point - clouds.cameraFromCentre)) / clouds.tileWidth;
    float value = textureLod(cloudVolume, c, 0.0).r;
    float coverage = clouds.coverage * textureLod(weatherMap, point / r, 0.0).r;
    value = CloudCoverageRemap(value, coverage);
    float density = CloudDensityFromTexture(value, CloudHeightSignal(r, clouds.bottomRadius, clouds.topRadius));  // Eq. 13-14
    return density < 0.0 ? density : density * clouds.densityScale;
}

// Optical depth per unit extinction (the integral of the density, km) from `point` towards
// the sun: clouds.sunSamples density samples spread over the sun ray's way through the
// layer, or over `maxLength` km of it where that way is longer. 0 without clouds.
float CloudDensityPathToSun(vec3 point, vec3 sun, float maxLength) {
    if (clouds.enabled == 0) return 0.0;
    float r = length(point);
    vec2 first;
    vec2 second;
    int count = CloudLayerIntervals(r, dot(point, sun) / r, 1.0e9, clouds.bottomRadius, clouds.topRadius, first, second);
    if (count == 0) return 0.0;
    float way = min(first.y - first.x, maxLength);
    float step = way / float(max(clouds.sunSamples, 1));
    float path = 0.0;
    for (int i = 0; i < clouds.sunSamples; ++i)
        path += max(CloudDensity(point + sun * (first.x + (float(i) + 0.5) * step)), 0.0) * step;
    return path;
}

// The clouds' transmittance towards the sun (Michelic Eq. 15 along the sun ray: T_sun).
float CloudSunTransmittance(vec3 point, vec3 sun, float maxLength) {
    return exp(-clouds.extinction * CloudDensityPathToSun(point, sun, maxLength));
}
