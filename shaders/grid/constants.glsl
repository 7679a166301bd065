// The projected grids' constants that the C++ counts with too (src/grid/constants.h compiles this
// file as C++, as src/render/bindings.h does shaders/common/bindings.glsl): one source of truth.

// The frustum the grids' patches are culled against, its side planes' slopes this much wider than
// the view's (grid/tessellation.glsl's outsideFrustum; src/grid/view_cull.h's blocks, on the CPU).
const float FRUSTUM_WIDENING = 1.2;

// The most a tessellated segment's chord of the sphere may sag, in pixels where it is nearest:
// at the limb the sag is seen edge-on, and the silhouette recedes by it (grid/tessellation.glsl's
// edgeSegments; src/grid/grid_stride.cpp's stride cap).
const float MAX_SAG_PIXELS = 0.25;

// The most the terrain's chords may sag below the sphere, m. The G-buffer is formed at the mesh's
// point, so a chord's sag moves what a pixel shows sideways (sag x tan of the incidence); at
// the grid's cells that was under a kilometre, and with the grid's stride from space
// (src/grid/grid_stride.h) patches of 8 cells at level 1 sagged 38 km at 160x90 and the land came
// out 2.3 % darker. With segments under 1 km of sag, stride 8 against stride 1 there: mean
// luminance +0.01 %, mean relative error 0.02 % (terrain/terrain.tesc).
const float TERRAIN_MAX_SAG_M = 1000.0;

// The grid's spacing at its centre against the even one (src/grid/projected_grid.h's
// gridVertexCoordinate, terrain/grid.glsl's gridCoordinateAt).
const float GRID_CENTRE_DENSITY = 0.05;

// Michelic Eq. 2's exponent n for the ocean's grid (src/ocean/ocean_pass.cpp; terrain/grid.glsl's
// gridPointOf is written for it).
const int OCEAN_GRID_EXPONENT = 4;

// The ocean mesh's far edges (ocean/edge_target.glsl): where even the highest crest spans under
// WAVE_VISIBLE_PIXELS on screen, its edges aim at up to OCEAN_FAR_EDGE_FACTOR times the target.
const float WAVE_VISIBLE_PIXELS = 0.25;
const float OCEAN_FAR_EDGE_FACTOR = 4.0;

// The chord sag, m, over which ocean/ocean.frag moves from the mesh's point to the sphere's (its
// "farness" rises from 0 to 1 between the two): beyond the second the mesh only says which
// pixels are sea (src/ocean/far_field.h).
const float OCEAN_NEAR_FIELD_SAG_M = 0.05;
const float OCEAN_FAR_FIELD_SAG_M = 0.5;
