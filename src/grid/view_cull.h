// Which parts of a projected grid can show anything in the view, on the CPU before the draw.
// The control stage culls each patch against the widened frustum (grid/tessellation.glsl's
// outsideFrustum), but only after the vertex stage evaluated its corners' heights and the control
// stage ran: on a software renderer both run on the single thread that submits the draw, for
// every patch of the grid. At the ground view most of the grid lies behind the camera or beside the
// view (the grid covers the whole cap out to the horizon's peaks, every way round), so the runs of
// patches (GridMesh::blocks(): up to 8 along a row) that cannot reach the view are not drawn at all.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "grid/grid_mesh.h"
#include "scene/camera.h"

namespace planet {

// For each of `blocks` (GridMesh::blocks(), draw order), whether it may show in the view of
// `camera` (aspect width / height): false only where the whole shell segment over the block, every
// direction its patches span (Eq. 1-4 at its grid points, widened for what lies between them) and
// every radius in [lowRadiusM, highRadiusM] (the lowest sea floor, the highest peak), lies outside
// one side plane of the frustum widened by FRUSTUM_WIDENING (grid/constants.glsl), or behind the
// camera; `sidewaysM`: how far the surface may move along the sphere from its grid point (the
// waves' horizontal displacement). Conservative: a block kept may still be culled patch by patch on
// the GPU.
std::vector<bool> gridBlocksInView(const std::vector<PatchRun>& blocks, const GridBlock& grid,
                                   const Camera& camera, double aspect, double lowRadiusM, double highRadiusM,
                                   double sidewaysM = 0.0);

// For each of `blocks`, whether `covered(centre, angle)` holds for the cap of the directions its
// patches span (its unit centre and angular radius, rad, as gridBlocksInView bounds them), or else,
// where `partly(centre, angle)` says some of that cap may be covered, for each of its patches' caps;
// false without asking where `among` (one flag per block, or empty for all) is false. The sea asks
// whether the land stands above its highest crest over the whole cap (src/ocean/ocean_pass.cpp): its
// control stage would cull each of those patches (ocean/ocean.tesc, overLand) after running for it.
using CapTest = std::function<bool(const glm::dvec3& centre, double angle)>;
std::vector<bool> gridBlocksWhere(const std::vector<PatchRun>& blocks, const GridBlock& grid,
                                  const std::vector<bool>& among, const CapTest& covered, const CapTest& partly);

}  // namespace planet
