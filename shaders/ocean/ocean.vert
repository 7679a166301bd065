// Ocean: one vertex per grid point of its own projected grid; tessellation does the rest.
// With OCEAN_FLAT_MIRROR (the sea seen from high up), also the clouds' change to the sea's
// reflection along the mean surface's mirror ray, once per grid point (ocean/
// cloud_reflection.glsl): the grid's points are a fixed number whatever the resolution; with
// OCEAN_SMOOTH_MIRROR (higher still: no pixel resolves a wave) the whole reflected sky there.
#include "common/frame_uniforms.glsl"
#include "terrain/grid.glsl"
#include "atmosphere/interface.glsl"
#include "clouds/cloud_march.glsl"
#include "ocean/cloud_reflection.glsl"

layout(location = 0) in vec2 gridCoordinate;
out vec2 vGrid;
out vec3 vGridReflection;  // dL_C, or L_sky + dL_C with OCEAN_SMOOTH_MIRROR (0 without either: per pixel)

void main() {
    vGrid = gridCoordinate;
    vGridReflection = vec3(0.0);
#if OCEAN_FLAT_MIRROR
    dvec3 direction = gridDirection(gridCoordinate);
    vec3 up = vec3(direction);
    vec3 sphere = cameraRelative(direction, gridSphereRadius());  // m, the mean sea surface
    vec3 point = cameraFromPlanetCentreKm() + sphere / M_PER_KM;  // km from the planet centre
    vec3 reflected = SeaReflectedRay(normalize(sphere), up, up);
#if OCEAN_SMOOTH_MIRROR
    vGridReflection = ReflectedMarch(point, reflected, frame.sunDirection);
#else
    vGridReflection = CloudReflectionChange(point, reflected, frame.sunDirection);
#endif
#endif
}
