// The explorer's first-use panel layout and its time-of-day control, on the CPU (the window
// itself is tested under Xvfb in test_cli.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "app/panels.h"
#include "scene/scene.h"

using namespace planet;

TEST(ExplorerLayout, PanelsLeaveSeventyPercentOfA1280x720ViewFree) {
    // ImGui's title bar is about 19 px with the default font; 24 leaves room.
    for (const auto& [w, h] : {std::pair{1280.0f, 720.0f}, std::pair{1920.0f, 1080.0f}}) {
        const std::vector<PanelPlacement> layout = initialPanelLayout(w, h);
        const double covered = panelCoverage(layout, w, h, 24.0f);
        std::printf("%gx%g: panels cover %.1f %% at first use\n", w, h, 100.0 * covered);
        EXPECT_LE(covered, 0.30) << w << "x" << h;
        EXPECT_GT(covered, 0.05) << "the frame-time panel is open";
    }
    const std::vector<PanelPlacement> layout = initialPanelLayout(1280.0f, 720.0f);
    ASSERT_EQ(layout.size(), 4u);
    for (const PanelPlacement& p : layout) {
        EXPECT_EQ(p.collapsed, p.name != "Frame time") << p.name;
        EXPECT_GE(p.x, 0.0f) << p.name;
        EXPECT_LE(p.x + p.width, 1280.0f) << p.name << " inside the window";
    }
    // Coverage counts overlaps once: two identical open panels cover what one does.
    std::vector<PanelPlacement> twice = {layout[0], layout[0]};
    EXPECT_DOUBLE_EQ(panelCoverage(twice, 1280.0f, 720.0f, 24.0f), panelCoverage({layout[0]}, 1280.0f, 720.0f, 24.0f));
    EXPECT_NEAR(panelCoverage({layout[0]}, 1280.0f, 720.0f, 24.0f), 430.0 * 260.0 / (1280.0 * 720.0), 1e-9);
}

TEST(ExplorerLayout, TimeOfDayTurnsThePlanetUnderTheSun) {
    SunParams sun;
    sun.latitude_deg = 0.0;
    const glm::dvec3 place = directionFromLatLon(0.0, 10.0);
    auto elevationDeg = [&] {
        return glm::degrees(std::asin(glm::dot(directionFromLatLon(sun.latitude_deg, sun.longitude_deg), place)));
    };
    setLocalSolarHour(sun, place, 12.0);
    EXPECT_NEAR(sun.longitude_deg, 10.0, 1e-12);
    EXPECT_NEAR(elevationDeg(), 90.0, 1e-6);
    for (double hour : {6.0, 18.0}) {
        setLocalSolarHour(sun, place, hour);
        EXPECT_NEAR(elevationDeg(), 0.0, 1e-9) << hour;  // sunrise, sunset at the equinox
    }
    setLocalSolarHour(sun, place, 0.0);
    EXPECT_NEAR(elevationDeg(), -90.0, 1e-6);  // midnight
    // Morning: the sun in the east (towards +longitude of the place).
    setLocalSolarHour(sun, place, 9.0);
    EXPECT_GT(sun.longitude_deg, 10.0);
    // Round trip anywhere, longitudes kept in [-180, 180], the season untouched.
    sun.latitude_deg = 23.0;
    for (double lon : {-179.0, -60.0, 0.0, 135.0, 179.5})
        for (double hour : {0.0, 0.5, 7.25, 12.0, 23.9}) {
            const glm::dvec3 p = directionFromLatLon(45.0, lon);
            setLocalSolarHour(sun, p, hour);
            EXPECT_NEAR(localSolarHour(sun, p), hour, 1e-9) << lon << " " << hour;
            EXPECT_GE(sun.longitude_deg, -180.0);
            EXPECT_LE(sun.longitude_deg, 180.0);
            EXPECT_EQ(sun.latitude_deg, 23.0);
        }
}
