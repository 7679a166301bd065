// G-buffer layout shared by the passes that write and read it (see src/render/render_targets.h).
//   location 0  normal    RGBA16F  xyz: unit surface normal, world axes; w: the ground's height
//                                  above sea level, m (the height field's, not the mesh's)
//   location 1  albedo    RGBA8    rgb: linear albedo
//   location 2  material  RGBA8    r: material id / 255, g: roughness, b: the spread of the
//                                  detail's slopes the ground's filter removed (per component,
//                                  rise over run, [0, 1]; terrain/detail.glsl), lit by the
//                                  surface light as an expected clamped cosine
//   depth       DEPTH32F  reversed-Z (1 at the near plane, 0 at infinity; 0 = nothing)
