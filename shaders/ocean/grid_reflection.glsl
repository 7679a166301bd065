// The reflection at the ocean grid's points where the sea is a flat (or smooth) mirror to every
// pixel (ocean/cloud_reflection.glsl): formed once per point and frame by
// ocean/grid_reflection.comp, read by ocean.tese between the points (ocean/grid_reflection_points.glsl).
// A compute pass rather than the vertex stage: a software renderer runs the vertex stage on the
// submitting thread alone, and again for a point in each run of patches that uses it (the grid is
// drawn in runs of 15 patches there, src/grid/grid_mesh.h: each point about twice); the dispatch
// runs each point once, on every core. Needs terrain/grid.glsl, atmosphere/interface.glsl,
// clouds/cloud_march.glsl and ocean/cloud_reflection.glsl.

// What the grid's point at `gridCoordinate` gives the reflection, along the mean surface's mirror
// ray: dL_C, or with OCEAN_SMOOTH_MIRROR the whole reflected sky, L_sky + dL_C (the march itself).
vec3 GridReflection(vec2 gridCoordinate) {
    dvec3 direction = gridDirection(gridCoordinate);
    vec3 up = vec3(direction);
    vec3 sphere = cameraRelative(direction, gridSphereRadius());  // m, the mean sea surface
    vec3 point = cameraFromPlanetCentreKm() + sphere / M_PER_KM;  // km from the planet centre
    vec3 reflected = SeaReflectedRay(normalize(sphere), up, up);
#if OCEAN_SMOOTH_MIRROR
    return ReflectedMarch(point, reflected, frame.sunDirection);
#else
    return CloudReflectionChange(point, reflected, frame.sunDirection);
#endif
}
