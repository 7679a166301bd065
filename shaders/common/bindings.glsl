// Every texture unit and buffer binding of the frame, written once (STYLE habit 3).
//
// Compiled as GLSL (layout(binding = X) takes a constant expression since GLSL 4.40) and
// as C++ (src/render/bindings.h includes this file), so the C++ side binds exactly where
// the shaders read: no literal unit number appears anywhere else. A texture keeps its unit
// in every pass, so passes never rebind what an earlier pass bound for the same reader.

// Uniform blocks (std140; C++ mirrors static_assert their layout).
const int BLOCK_FRAME = 0;       // FrameBlock: camera, sun, viewport, history (common/frame_uniforms.glsl)
const int BLOCK_ATMOSPHERE = 1;  // AtmosphereBlock: the model's parameters (atmosphere/uniforms.glsl)
const int BLOCK_TERRAIN = 2;     // TerrainBlock: the height field's shape and the terrain's look (terrain/terrain_block.glsl)
const int BLOCK_GRID = 3;        // GridBlock: the projected grid of the pass that draws (terrain/grid.glsl)
const int BLOCK_OCEAN = 4;       // OceanBlock: the sea's parameters (ocean/ocean_block.glsl)
const int BLOCK_CLOUDS = 5;      // CloudBlock: the cloud layer (clouds/cloud_block.glsl)
const int BLOCK_TERRAIN_NEAR = 6; // TerrainNearBlock: the height field near the camera (terrain/terrain_block.glsl)
const int BLOCK_TERRAIN_NEAR_GRID = 7;  // NearHeightGridBlock: where the near height grid lies (terrain/near_height_grid.glsl)

// Shader storage buffers (std430).
const int BUFFER_PROBE_INPUT = 0;   // the compute probes' inputs and outputs (tests and sky-probe)
const int BUFFER_PROBE_OUTPUT = 1;
const int BUFFER_OCEAN_WAVES = 3;   // one record per wave (ocean/ocean_waves.glsl)
const int BUFFER_CLOUD_STATISTICS = 4;  // the sky pass's march step counts, when asked (planet bench)
const int BUFFER_SKY_REFINE = 5;    // the pixels the temporal reconstruction marks for a full-rate march (render/pixel_list.glsl)
const int BUFFER_SEA_REFLECTION_LIST = 6;  // the sea's pixels that march their own reflection (ocean/sea_reflection.frag)
const int BUFFER_TERRAIN_REFLECTION_LIST = 7;  // the sea's pixels that may reflect the terrain (ocean/terrain_reflection.glsl)
const int BUFFER_OCEAN_GRID_POINTS = 8;      // the ocean grid's coordinates, a vec2 per point (src/grid/grid_mesh.h)
const int BUFFER_TERRAIN_SHADOW_LIST = 9;  // the sea's pixels whose terrain shadow is marched after the ocean (render/terrain_shadow_list.glsl)
const int BUFFER_LAND_ON_SCREEN = 10;  // whether any ground above the sea is on screen (render/land_on_screen.glsl)
const int BUFFER_TERRAIN_SHADOW_SAMPLE_MARCHES = 11;  // the terrain shadow's samples marched after the pass (render/terrain_shadow_sample_marches.comp)

// Image units (the passes that store into a frame target from a compute shader).
const int IMAGE_HDR_RADIANCE = 0;   // RGBA16F radiance arriving at the camera
const int IMAGE_SKY_MEDIUM = 1;     // RGBA32UI the sky passes' T, S and samples (render/sky_medium.glsl)
const int IMAGE_SURFACE_RADIANCE = 2;  // RGBA16F radiance leaving the surface (ocean/sea_reflection.comp adds to it)
const int IMAGE_SEA_REFLECTION = 3;    // RGBA32F the sea's reflected ray and weight (ocean/terrain_reflection.comp lowers it)
const int IMAGE_TERRAIN_SHADOW_SAMPLES = 5;  // RG32F the terrain shadow's samples (render/terrain_shadow_sample_marches.comp writes the marched ones)
const int IMAGE_OCEAN_GRID_REFLECTION = 4;  // RGBA32F N x N: the reflection at the ocean grid's points (ocean/grid_reflection.comp)
const int IMAGE_TERRAIN_NEAR_GRID = 6;      // RGBA32F N x N: the height field and its gradient near the camera (terrain/near_height_grid.comp)

// Texture units.
const int UNIT_GBUFFER_NORMAL = 0;          // RGBA16F world normal
const int UNIT_GBUFFER_ALBEDO = 1;          // RGBA8 linear albedo
const int UNIT_GBUFFER_MATERIAL = 2;        // RGBA8 material id / 255, roughness, detail slope spread (gbuffer.glsl)
const int UNIT_GBUFFER_DEPTH = 3;           // DEPTH32F reversed-Z
const int UNIT_TRANSMITTANCE = 4;           // atmosphere tables (atmosphere/interface.glsl)
const int UNIT_SCATTERING = 5;
const int UNIT_SINGLE_MIE = 6;
const int UNIT_IRRADIANCE = 7;
const int UNIT_ELEK_SCATTERING = 8;
const int UNIT_ELEK_SINGLE_MIE = 9;
const int UNIT_CONTINENTS = 10;             // RGBA32F cube map (noise/continents.h)
const int UNIT_SURFACE_RADIANCE = 11;       // RGBA16F radiance leaving the surface point, no air in it
const int UNIT_SURFACE_DISTANCE = 12;       // R32F distance along the view ray to the surface point, m (0: none)
const int UNIT_SEABED_RADIANCE = 13;        // copy of the surface radiance before the sea is drawn over it
const int UNIT_SEABED_DEPTH = 14;           // copy of the G-buffer depth before the sea
const int UNIT_HDR_RADIANCE = 15;           // RGBA16F radiance arriving at the camera (tone mapping reads it)
const int UNIT_CLOUD_VOLUME = 16;           // R16F tiling 3D density (noise/cloud_volume.h), GL_REPEAT
const int UNIT_WEATHER_MAP = 17;            // cube map: coverage, cloud type (noise/weather_map.h)
const int UNIT_SPARSE_INSCATTER = 18;       // RGBA16F, a quarter size: the reduced-rate march's S, reprojection km
const int UNIT_SPARSE_TRANSMITTANCE = 19;   // RGBA16F, a quarter size: its T, the clouds' opacity
const int UNIT_SPARSE_DISTANCE_ERROR = 26;    // RG32F, a quarter size: each sample's surface distance, m, and history error
const int UNIT_HISTORY_SKY_MEDIUM = 20;     // RGBA32UI: the previous frame's T, S and samples (render/sky_medium.glsl)
const int UNIT_HISTORY_SURFACE_DISTANCE = 22;   // R32F: the previous frame's surface distance, m
const int UNIT_HISTORY_RADIANCE = 24;       // RGBA16F: the previous frame's hdr (anti-aliased when the explorer's TAA is on)
const int UNIT_TERRAIN_DETAIL = 23;         // RGBA16F tiling detail height field, mipmapped, GL_REPEAT (terrain/detail_texture.h)
const int UNIT_TERRAIN_SHADOW = 25;         // RG32F, half size: the terrain shadow's samples (render/terrain_shadow.frag)
const int UNIT_SEA_REFLECTION = 21;         // RGBA32F: the sea's reflected ray and the clouds' weight there (ocean/sea_light.frag)
const int UNIT_SEA_SKY_REFLECTION = 28;     // RGBA32F: the sky the sea reflected where the terrain may be reflected, its distance (ocean/sea_light.frag)
const int UNIT_SEA_REFLECTION_SAMPLES = 27; // RGBA16F, half size: the clouds' change to the sea's reflection (ocean/sea_reflection.frag)
const int UNIT_MESH_SURFACE_0 = 30;         // RGBA32F x 3: what a mesh's fragments leave for a pass over its pixels (terrain/mesh_surface.glsl)
const int UNIT_MESH_SURFACE_1 = 31;
const int UNIT_MESH_SURFACE_2 = 32;
const int UNIT_CONTINENT_MAX = 33;          // R32F cube map, a mip level per level (src/terrain/continent_bound.h)
const int UNIT_TERRAIN_NEAR_GRID = 35;      // RGBA32F N x N: the height field and its gradient near the camera (terrain/near_height_grid.glsl)
const int UNIT_CLEAR_SKY = 34;              // R32F cube map: the angle around a point where no cloud is, for sure (src/clouds/clear_sky.h)
const int UNIT_OCEAN_GRID_REFLECTION = 29;  // RGBA32F N x N, bilinear: the reflection at the ocean grid's points (ocean/sea_light.frag)
