// Tests for the sphere's screen bound (render/screen_bound.h), which the sky passes are
// scissored to: every pixel whose centre's ray meets the sphere must lie in it (checked by
// brute force against a ray-sphere test in double), and it must be close to the tightest
// rectangle (else it saves nothing). CPU only.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include "render/frame_uniforms.h"
#include "render/screen_bound.h"
#include "scene/camera.h"

namespace planet {
namespace {

struct Hits {
    ScreenRect box{{1 << 30, 1 << 30}, {-(1 << 30), -(1 << 30)}};  // the hit pixels' bounding box, [min, max)
    long long count = 0;
};

// The pixels whose centre's ray (as the passes form it: through viewFromClip) meets the sphere
// of `radius` around the world origin.
Hits hitPixels(const Camera& camera, glm::ivec2 size, glm::dvec2 jitter, double radius) {
    const glm::dmat4 viewFromClip = glm::inverse(jitteredClipFromView(camera, size, jitter));
    const glm::dmat3 worldFromView = camera.worldFromView();
    const glm::dvec3 o = camera.position;
    Hits hits;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const glm::dvec2 ndc = (glm::dvec2(x, y) + 0.5) / glm::dvec2(size) * 2.0 - 1.0;
            const glm::dvec4 v = viewFromClip * glm::dvec4(ndc, 0.5, 1.0);
            const glm::dvec3 d = glm::normalize(worldFromView * (glm::dvec3(v) / v.w));
            const double b = glm::dot(o, d), c = glm::dot(o, o) - radius * radius;
            const bool hit = c <= 0.0 || (b < 0.0 && b * b - c >= 0.0);
            if (!hit) continue;
            ++hits.count;
            hits.box.min = glm::min(hits.box.min, glm::ivec2(x, y));
            hits.box.max = glm::max(hits.box.max, glm::ivec2(x + 1, y + 1));
        }
    }
    return hits;
}

ScreenRect boundOf(const Camera& camera, glm::ivec2 size, glm::dvec2 jitter, double radius) {
    return sphereScreenBound(jitteredClipFromView(camera, size, jitter), glm::transpose(camera.worldFromView()),
                             -camera.position, radius, size);
}

Camera lookingAt(const glm::dvec3& position, const glm::dvec3& target, double fovDeg) {
    Camera c;
    c.position = position;
    const glm::dvec3 forward = glm::normalize(target - position);
    const glm::dvec3 helper = std::abs(forward.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, helper));
    c.orientation = orientationFromAxes(right, glm::cross(right, forward), forward);
    c.fovY_rad = glm::radians(fovDeg);
    return c;
}

TEST(ScreenBound, HoldsEveryPixelThatSeesTheSphereAndLittleMore) {
    // Cameras from just outside the sphere to far away, looking anywhere (at it, past its limb,
    // away), odd sizes, sub-pixel jitter: no pixel that meets the sphere is outside the bound,
    // and the bound is the hits' box within its margin (a pixel and the rounding to pixel
    // centres) and the polygon's overshoot (atan(tan a / cos(pi/128)), magnified by the
    // projection where the cone grazes the camera's plane): 5 pixels (the worst case, 4 pixels,
    // a sliver of the sphere along the screen's edge, whose width grows as the root of its depth).
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double radius = 6.42e6;
    int bounded = 0, partial = 0;
    for (int i = 0; i < 300; ++i) {
        const glm::dvec3 at = glm::normalize(glm::dvec3(unit(random), unit(random), unit(random)));
        const double distance = radius * std::pow(10.0, 0.0005 + 2.5 * (0.5 + 0.5 * unit(random)));
        const glm::dvec3 look = glm::dvec3(unit(random), unit(random), unit(random)) * radius * 1.5;
        const Camera camera = lookingAt(at * distance, look, 20.0 + 50.0 * (0.5 + 0.5 * unit(random)));
        const glm::ivec2 size(61 + i % 40, 37 + (i * 7) % 30);
        const glm::dvec2 jitter(0.5 * unit(random), 0.5 * unit(random));
        const Hits hits = hitPixels(camera, size, jitter, radius);
        const ScreenRect bound = boundOf(camera, size, jitter, radius);
        if (hits.count > 0) {
            ASSERT_FALSE(bound.empty()) << i;
            EXPECT_LE(bound.min.x, hits.box.min.x) << i;
            EXPECT_LE(bound.min.y, hits.box.min.y) << i;
            EXPECT_GE(bound.max.x, hits.box.max.x) << i;
            EXPECT_GE(bound.max.y, hits.box.max.y) << i;
        }
        if (bound.coversScreen(size)) continue;
        ++bounded;
        if (hits.count == 0) {  // off screen, or a sliver of overshoot along an edge
            EXPECT_LE(bound.area(), 4LL * std::max(size.x, size.y)) << i;
            continue;
        }
        ++partial;
        const glm::ivec2 slack = glm::ivec2(5);
        EXPECT_GE(bound.min.x, hits.box.min.x - slack.x) << i;
        EXPECT_GE(bound.min.y, hits.box.min.y - slack.y) << i;
        EXPECT_LE(bound.max.x, hits.box.max.x + slack.x) << i;
        EXPECT_LE(bound.max.y, hits.box.max.y + slack.y) << i;
    }
    // The cases exercise the bound, not just its whole-screen fallback.
    EXPECT_GT(bounded, 100);
    EXPECT_GT(partial, 50);
}

TEST(ScreenBound, ASphereAheadSpansItsAnalyticAngle) {
    // Straight ahead at distance d, radius r: the disc's half-width on screen is
    // tan(asin(r / d)) / tan(fovY / 2) of the half-height, in NDC.
    const double radius = 1.0, distance = 4.0;
    const Camera camera = lookingAt({0.0, 0.0, distance}, {0.0, 0.0, 0.0}, 60.0);
    const glm::ivec2 size(400, 400);
    const double halfPx = std::tan(std::asin(radius / distance)) / std::tan(glm::radians(30.0)) * 200.0;
    const ScreenRect bound = boundOf(camera, size, glm::dvec2(0.0), radius);
    for (int axis = 0; axis < 2; ++axis) {
        EXPECT_NEAR(bound.min[axis], 200.0 - halfPx, 3.0);
        EXPECT_NEAR(bound.max[axis], 200.0 + halfPx, 3.0);
    }
}

TEST(ScreenBound, InsideItIsTheWholeScreenAndBehindTheCameraNothing) {
    const glm::ivec2 size(64, 36);
    const Camera inside = lookingAt({0.0, 0.0, 0.5}, {1.0, 0.0, 0.5}, 60.0);
    EXPECT_TRUE(boundOf(inside, size, glm::dvec2(0.0), 1.0).coversScreen(size));
    const Camera nearSurface = lookingAt({0.0, 0.0, 1.0005}, {0.0, 0.0, 0.0}, 60.0);
    EXPECT_TRUE(boundOf(nearSurface, size, glm::dvec2(0.0), 1.0).coversScreen(size));
    const Camera away = lookingAt({0.0, 0.0, 10.0}, {0.0, 0.0, 20.0}, 60.0);
    EXPECT_TRUE(boundOf(away, size, glm::dvec2(0.0), 1.0).empty());
    EXPECT_EQ(hitPixels(away, size, glm::dvec2(0.0), 1.0).count, 0);
}

TEST(ScreenBound, TheSunsDiscBoundHoldsEveryPixelWithinItsAngularRadius) {
    // The sky passes leave the disc's code out off this rectangle (render/sky_air.glsl, NO_SUN_DISC):
    // every pixel whose centre's ray lies within the disc's angular radius of the sun (where
    // SunDiscRadiance is not 0) must be in it. Suns near and across the screen's edges and corners,
    // narrow and wide views, jitter; the bound is a few pixels around the disc, and empty where the
    // disc lies off the view.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double angularRadius = 0.004675;  // the sun's, rad
    int seen = 0, offView = 0, withPixels = 0;
    for (int i = 0; i < 400; ++i) {
        const double fovDeg = i % 2 ? 4.0 + 4.0 * (0.5 + 0.5 * unit(random)) : 30.0 + 50.0 * (0.5 + 0.5 * unit(random));
        const Camera camera = lookingAt({0.0, 0.0, 0.0}, {unit(random), unit(random), unit(random)}, fovDeg);
        const glm::ivec2 size(61 + i % 40, 37 + (i * 7) % 30);
        const glm::dvec2 jitter(0.5 * unit(random), 0.5 * unit(random));
        // A sun about the view's corner: in, out and across the edges.
        const glm::dmat3 worldFromView = camera.worldFromView();
        const double halfY = glm::radians(fovDeg) / 2.0, halfX = std::atan(std::tan(halfY) * size.x / size.y);
        const glm::dvec3 sunView = glm::normalize(glm::dvec3(std::tan(halfX * 1.1 * unit(random)),
                                                             std::tan(halfY * 1.1 * unit(random)), -1.0));
        const glm::dvec3 sun = worldFromView * sunView;
        const glm::dmat4 viewFromClip = glm::inverse(jitteredClipFromView(camera, size, jitter));
        const ScreenRect bound = sunDiscScreenBound(jitteredClipFromView(camera, size, jitter),
                                                    glm::transpose(worldFromView), sun, angularRadius, size);
        int inDisc = 0;
        for (int y = 0; y < size.y; ++y) {
            for (int x = 0; x < size.x; ++x) {
                const glm::dvec2 ndc = (glm::dvec2(x, y) + 0.5) / glm::dvec2(size) * 2.0 - 1.0;
                const glm::dvec4 v = viewFromClip * glm::dvec4(ndc, 0.5, 1.0);
                const glm::dvec3 d = glm::normalize(worldFromView * (glm::dvec3(v) / v.w));
                if (std::acos(std::min(glm::dot(d, sun), 1.0)) >= angularRadius) continue;
                ++inDisc;
                ASSERT_TRUE(x >= bound.min.x && x < bound.max.x && y >= bound.min.y && y < bound.max.y)
                    << i << ": pixel " << x << "," << y << " sees the disc outside the bound";
            }
        }
        if (bound.empty()) {
            ++offView;
            continue;
        }
        ++seen;
        // The disc's diameter in pixels (magnified off the axis by up to 1 + tan^2 of the corner's
        // angle), the pixel added each way and the rounding to centres.
        const double stretch = 1.0 + 1.21 * (std::pow(std::tan(halfX), 2) + std::pow(std::tan(halfY), 2));
        const double discPx = angularRadius / std::tan(halfY) * size.y * stretch;
        EXPECT_LE(bound.max.x - bound.min.x, discPx + 6.0) << i;
        EXPECT_LE(bound.max.y - bound.min.y, discPx + 6.0) << i;
        if (inDisc > 0) ++withPixels;
    }
    EXPECT_GT(withPixels, 50);
    EXPECT_GT(seen, 150);  // the cases exercise both sides
    EXPECT_GT(offView, 20);
    // Behind the camera: nothing.
    const Camera camera = lookingAt({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 60.0);
    EXPECT_TRUE(sunDiscScreenBound(jitteredClipFromView(camera, {64, 36}, glm::dvec2(0.0)),
                                   glm::transpose(camera.worldFromView()), {0.0, 0.0, -1.0}, angularRadius, {64, 36})
                    .empty());
}

TEST(ScreenBound, IntersectionIsThePixelsInBoth) {
    const ScreenRect a{{2, 3}, {10, 8}}, b{{5, 0}, {20, 6}};
    const ScreenRect both = intersection(a, b);
    EXPECT_EQ(both.min, glm::ivec2(5, 3));
    EXPECT_EQ(both.max, glm::ivec2(10, 6));
    EXPECT_TRUE(intersection(a, ScreenRect{{10, 0}, {12, 9}}).empty());  // side by side
    EXPECT_TRUE(intersection(a, ScreenRect{}).empty());
}

TEST(ScreenBound, BlocksAroundHoldTheBlocksNextToTheRect) {
    const ScreenRect rect{{9, 4}, {23, 13}};  // pixels 9..22, 4..12
    const ScreenRect b = blocksAround(rect, 4, {10, 10});
    EXPECT_EQ(b.min, glm::ivec2(1, 0));  // block 2 holds pixel 9; one more each way
    EXPECT_EQ(b.max, glm::ivec2(7, 5));  // block 5 holds pixel 22, block 3 pixel 12
    EXPECT_TRUE(blocksAround(ScreenRect{}, 4, {10, 10}).empty());
    const ScreenRect all = blocksAround({{0, 0}, {40, 40}}, 4, {10, 10});
    EXPECT_EQ(all.min, glm::ivec2(0));
    EXPECT_EQ(all.max, glm::ivec2(10));
}

// The bands and the rectangle cover every pixel of the screen exactly once, wherever the
// rectangle lies (inside, across an edge or a corner, beyond the screen, empty).
TEST(ScreenBound, BandsAroundAndTheRectTileTheScreen) {
    const glm::ivec2 size{23, 17};
    const ScreenRect cases[] = {{{5, 4}, {12, 9}},   {{-3, 2}, {8, 30}}, {{0, 0}, {23, 17}}, {{15, -4}, {40, 6}},
                                {{30, 30}, {40, 40}}, {}, {{3, 3}, {4, 4}}};
    for (const ScreenRect& rect : cases) {
        SCOPED_TRACE(testing::Message() << rect.min.x << "," << rect.min.y << " " << rect.max.x << "," << rect.max.y);
        std::vector<int> covered(std::size_t(size.x * size.y), 0);
        const auto mark = [&](const ScreenRect& r) {
            for (int y = std::max(r.min.y, 0); y < std::min(r.max.y, size.y); ++y)
                for (int x = std::max(r.min.x, 0); x < std::min(r.max.x, size.x); ++x) ++covered[std::size_t(y * size.x + x)];
        };
        mark(rect);
        for (const ScreenRect& band : bandsAround(rect, size)) {
            if (band.empty()) continue;
            EXPECT_GE(band.min.x, 0);  // scissor boxes on the screen
            EXPECT_GE(band.min.y, 0);
            EXPECT_LE(band.max.x, size.x);
            EXPECT_LE(band.max.y, size.y);
            mark(band);
        }
        EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), size.x * size.y);
    }
}

}  // namespace
}  // namespace planet
