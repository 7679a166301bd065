// Where a view ray from the camera meets the mean sea surface's sphere (ocean.seaLevel above the
// planet radius). Include after common/frame_uniforms.glsl and ocean/ocean_block.glsl.

// The distance along the unit `dir` (world axes, from the camera) to the sea's sphere, m, where
// the ray meets it from above (the nearer root); -1 where it does not, or the camera is under
// the sea. In the form t = c / (-b + sqrt(b^2 - c)), c = h (2 R + h) from the camera's height h
// above the sea (formed in double on the CPU: frame.cameraDepthBelowSea), which subtracts
// nothing of planet size: exact to float's rounding from a beach to deep space.
float seaSphereDistance(vec3 dir) {
    float aboveSea = -frame.cameraDepthBelowSea;
    float seaRadius = frame.planetRadius + ocean.seaLevel;
    float b = (seaRadius + aboveSea) * dot(dir, frame.cameraUp);
    float c = aboveSea * (2.0 * seaRadius + aboveSea);
    float discriminant = b * b - c;
    if (aboveSea <= 0.0 || b >= 0.0 || discriminant < 0.0) return -1.0;
    return c / (-b + sqrt(discriminant));
}
