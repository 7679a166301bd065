// The ocean program's mirror modes (src/ocean/ocean_pass.cpp defines one): OCEAN_FLAT_MIRROR, the
// clouds' change to the reflection from the grid's points; OCEAN_SMOOTH_MIRROR, the whole
// reflection from them, a flat mirror too (ocean/cloud_reflection.glsl says why).
#ifndef OCEAN_SMOOTH_MIRROR
#define OCEAN_SMOOTH_MIRROR 0
#endif
#ifndef OCEAN_FLAT_MIRROR
#define OCEAN_FLAT_MIRROR OCEAN_SMOOTH_MIRROR
#endif
