// What the CPU says of a view ray and the clouds, for the tests of render/sky_no_cloud.frag's marks
// (tests/test_sky_march_split.cpp, tests/test_temporal.cpp): the same rules from the CPU's own intervals
// (clouds/cloud_model.glsl compiled as C++) and clear sky map (src/clouds/clear_sky.h).
#pragma once

#include <glm/glm.hpp>

#include "app/session.h"
#include "clouds/clear_sky.h"
#include "clouds/cloud_model.h"
#include "clouds/cloud_resources.h"
#include "gl_test_support.h"

namespace planet::test {

// Whether the ray through pixel (x, imageRow) to its surface point (`distanceM`, 0: none) meets no cloud by
// the CPU's intervals, the camera's clear distance from its vertical and the clear sky map around where each
// part enters the layer, with a margin of 2 % either way: 1 it meets none, 0 it reaches past the clear sky,
// -1 too near an edge to say.
inline int rayMeetsNoCloud(const Session& s, const clouds::CloudResources& clouds, double clearAxisKm, glm::ivec2 size, int x,
                 int imageRow, float distanceM) {
    const clouds::CloudBlock& block = clouds.block();
    const glm::dvec3 camera = s.camera.position / 1000.0;
    const glm::dvec3 dir = pixelRay(s.camera, size, x, imageRow);
    const double r = glm::length(camera);
    glm::dvec2 parts[2];
    const int crossings = clouds::glsl::CloudLayerIntervals(r, glm::dot(camera, dir) / r,
                                                            distanceM > 0.0f ? distanceM / 1000.0 : 1.0e30,
                                                            block.bottomRadius, block.topRadius, parts[0], parts[1]);
    if (crossings == 0) return 1;
    // Each rule's length against its clear distance: within it by 2 % (surely), beyond it by 2 % (surely not).
    const auto within = [](double length, double clearKm, double factor) { return length < factor * clearKm; };
    const double axisKm = parts[crossings - 1].y * glm::length(glm::cross(camera, dir)) / r;
    bool surely = within(axisKm, clearAxisKm, 0.98), maybe = within(axisKm, clearAxisKm, 1.02);
    bool partsSurely = true, partsMaybe = true;
    for (int k = 0; k < crossings; ++k) {
        const glm::dvec3 entry = camera + dir * parts[k].x;
        const double clearKm = block.bottomRadius * clouds::clearSkyChord(clouds.clearAngleAt(entry));
        partsSurely = partsSurely && within(parts[k].y - parts[k].x, clearKm, 0.98);
        partsMaybe = partsMaybe && within(parts[k].y - parts[k].x, clearKm, 1.02);
    }
    surely = surely || partsSurely;
    maybe = maybe || partsMaybe;
    return surely ? 1 : maybe ? -1 : 0;
}

}  // namespace planet::test
