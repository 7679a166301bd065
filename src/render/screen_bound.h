// The pixels a sphere can cover: a rectangle that a full-screen pass is scissored to, so that
// no fragment runs where the sphere is not (issue 15: no work for what is not seen). The sky
// passes are bounded by the air's sphere (atmosphere.top_radius_km: a ray that misses it sees
// space, the sun's disc at most), the passes that light the ground and the sea by the
// ground's highest sphere. A software renderer runs a pass's whole body for every pixel of a
// group, masked, even where the first line decided there is nothing to do, so from space
// (the planet a fifth of the frame) the passes paid for four fifths of nothing.
//
// The bound: the sphere seen from the camera is the cone of directions within
// asin(radius / distance) of its centre's. A polygon of kConeSides directions around the cone
// at the half-angle atan(tan a / cos(pi / kConeSides)) circumscribes it; cut by the four
// planes of the view's frustum (the screen's edges), what is left is a convex cone
// in front of the camera, which a perspective projection maps into the convex hull of its
// edges' images. Its bounding box, taken over the pixel centres (the passes' rays go through
// them) and widened by a pixel for rounding, is the rectangle: from low orbit, where the
// planet's cone reaches behind the camera, it is the part of the frame below the air's limb.
// Where the camera is in the sphere or within a thousandth of its radius, the whole screen;
// where the cone is behind the camera or beside the view, nothing.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace planet {

// Pixels [min, max) on each axis; empty when min >= max on either.
struct ScreenRect {
    glm::ivec2 min{0, 0};
    glm::ivec2 max{0, 0};

    bool empty() const { return max.x <= min.x || max.y <= min.y; }
    bool coversScreen(glm::ivec2 size) const { return min.x <= 0 && min.y <= 0 && max.x >= size.x && max.y >= size.y; }
    long long area() const { return empty() ? 0 : static_cast<long long>(max.x - min.x) * (max.y - min.y); }
};

inline constexpr int kConeSides = 128;

// The pixels whose centre's ray can meet the sphere (centre relative to the camera, world
// axes, and radius, in the same unit), under clipFromView (the frame's, jitter included) and
// viewFromWorld (the camera's rotation), on a screen of `size` pixels.
ScreenRect sphereScreenBound(const glm::dmat4& clipFromView, const glm::dmat3& viewFromWorld, const glm::dvec3& centre,
                            double radius, glm::ivec2 size);

// The pixels whose centre's ray can see the sun's disc (the cone of `angularRadius` around the unit
// `sunDirection`, world axes): the bound of a sphere of radius sin(angularRadius) one unit away; empty
// where the disc lies off the view. The sky passes run their programs without the disc off it.
ScreenRect sunDiscScreenBound(const glm::dmat4& clipFromView, const glm::dmat3& viewFromWorld,
                              const glm::dvec3& sunDirection, double angularRadius, glm::ivec2 size);

// The pixels in both (empty where they do not meet).
ScreenRect intersection(const ScreenRect& a, const ScreenRect& b);

// The blocks of `block` x `block` pixels (a reduced-rate target's texels) that hold a pixel of
// `rect` or of the blocks next to those (the reconstruction reads the 3x3 blocks around a pixel's).
ScreenRect blocksAround(const ScreenRect& rect, int block, glm::ivec2 blocks);

// The screen less `rect`: up to four bands (below, above, left, right of it), which with the
// rectangle (clamped to the screen) tile the screen without overlap; empty ones where the
// rectangle reaches the screen's edge. An empty rect leaves one band, the whole screen.
std::array<ScreenRect, 4> bandsAround(const ScreenRect& rect, glm::ivec2 size);

}  // namespace planet
