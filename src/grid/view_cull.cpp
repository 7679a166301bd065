#include "grid/view_cull.h"

#include <algorithm>
#include <cmath>

#include "grid/constants.h"
#include "grid/projected_grid.h"

namespace planet {

namespace {

// The block's directions' cap: the unit centre and the angular radius (rad) of every grid point
// of the block, times a margin for the patches' interiors between them (their grid lines curve
// by second-order amounts over a patch) and a patch's width more.
struct Cap {
    glm::dvec3 centre{0.0};
    double angle = 0.0;
};

Cap blockCap(const PatchRun& block, const GridBlock& grid, std::vector<glm::dvec3>& points) {
    const glm::dmat3 worldFromGrid(glm::dvec3(grid.worldFromGridColumns[0]), glm::dvec3(grid.worldFromGridColumns[1]),
                                   glm::dvec3(grid.worldFromGridColumns[2]));
    const auto direction = [&](int i, int j) {
        const glm::dvec2 g = gridVertexCoordinate(i, j, grid.pointsPerSide);
        return glm::normalize(worldFromGrid * predisplaced(g, grid.exponent, grid.zShift));  // Eq. 2-4, 1
    };
    points.clear();  // the caller's, kept between runs: no allocation per run and frame
    glm::dvec3 sum(0.0);
    for (int j = block.pointMin.y; j <= block.pointMax.y; ++j)
        for (int i = block.pointMin.x; i <= block.pointMax.x; ++i) {
            points.push_back(direction(i, j));
            sum += points.back();
        }
    Cap cap;
    cap.centre = glm::normalize(sum);
    double largestCos = 1.0;
    for (const glm::dvec3& d : points) largestCos = std::min(largestCos, glm::dot(d, cap.centre));
    const double pointsAngle = std::acos(std::clamp(largestCos, -1.0, 1.0));
    const double patches = std::max(block.pointMax.x - block.pointMin.x, block.pointMax.y - block.pointMin.y);
    cap.angle = pointsAngle * (1.25 + 1.0 / std::max(patches, 1.0));
    return cap;
}

}  // namespace

std::vector<bool> gridBlocksInView(const std::vector<PatchRun>& blocks, const GridBlock& grid,
                                   const Camera& camera, double aspect, double lowRadiusM, double highRadiusM,
                                   double sidewaysM) {
    // The widened side planes through the camera, in view space (x right, y up, -z forward): a point
    // is outside the one of +x where P00 x > w (-z) with P00 = 1 / (aspect tan(fovY / 2)), w the
    // widening (outsideFrustum's c.x > w c.w); their unit normals, outwards.
    const double w = grid_constant::FRUSTUM_WIDENING;
    const double p11 = 1.0 / std::tan(0.5 * camera.fovY_rad);
    const double p00 = p11 / aspect;
    const glm::dvec3 planes[5] = {glm::normalize(glm::dvec3(p00, 0.0, w)), glm::normalize(glm::dvec3(-p00, 0.0, w)),
                                  glm::normalize(glm::dvec3(0.0, p11, w)), glm::normalize(glm::dvec3(0.0, -p11, w)),
                                  glm::dvec3(0.0, 0.0, 1.0)};  // behind the camera
    const glm::dmat3 viewFromWorld = glm::transpose(camera.worldFromView());
    std::vector<bool> shown;
    shown.reserve(blocks.size());
    std::vector<glm::dvec3> points;
    for (const PatchRun& block : blocks) {
        const Cap cap = blockCap(block, grid, points);
        if (cap.angle >= 0.5 * 3.14159265358979) {  // a cap that large: no sphere bounds it tightly
            shown.push_back(true);
            continue;
        }
        // A ball about the point at radius `middle` on the cap's centre that holds the shell segment,
        // and so its convex hull, the patches' chords and triangles: the segment's farthest points from
        // it are its rim's (the distance to r (c cos t + u sin t) grows with t and is convex in r).
        const double c = std::cos(cap.angle);
        const double middle = 0.5 * (lowRadiusM + highRadiusM) * c;
        const auto reach = [&](double r) { return std::sqrt(std::max(r * r - 2.0 * r * middle * c + middle * middle, 0.0)); };
        const double radius = std::max(reach(lowRadiusM), reach(highRadiusM)) + sidewaysM;
        const glm::dvec3 centre = viewFromWorld * (cap.centre * middle - camera.position);
        bool outside = false;
        for (const glm::dvec3& n : planes) outside = outside || glm::dot(n, centre) > radius;
        shown.push_back(!outside);
    }
    return shown;
}

std::vector<bool> gridBlocksWhere(const std::vector<PatchRun>& blocks, const GridBlock& grid,
                                  const std::vector<bool>& among, const CapTest& covered, const CapTest& partly) {
    std::vector<bool> result(blocks.size(), false);
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        if (!among.empty() && !among[i]) continue;
        const auto holds = [&](const PatchRun& run) {
            const Cap cap = blockCap(run, grid, points);
            return cap.angle < 0.5 * 3.14159265358979 && covered(cap.centre, cap.angle);
        };
        const Cap cap = blockCap(blocks[i], grid, points);
        if (cap.angle < 0.5 * 3.14159265358979 && covered(cap.centre, cap.angle)) {
            result[i] = true;
            continue;
        }
        if (!partly(cap.centre, cap.angle)) continue;
        // Else patch by patch (a run's cap is the wider; the control stage tests each patch).
        bool all = true;
        for (int y = blocks[i].pointMin.y; all && y < blocks[i].pointMax.y; ++y)
            for (int x = blocks[i].pointMin.x; all && x < blocks[i].pointMax.x; ++x)
                all = holds(PatchRun{0, 1, {x, y}, {x + 1, y + 1}});
        result[i] = all;
    }
    return result;
}

}  // namespace planet
