// The frame's structure: declared passes in an order that holds, baked resources made in
// the prepare step only, the frame history and its reprojection terms, the jitter
// sequence, uniform blocks whose C++ mirrors match what the driver laid out, and aerial
// perspective computed in one place.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "atmosphere/uniforms.h"
#include "gl_test_support.h"
#include "render_support.h"
#include "grid/grid_mesh.h"
#include "ocean/ocean_block.h"
#include "render/bindings.h"
#include "render/frame_uniforms.h"
#include "render/renderer.h"
#include "terrain/near_height_grid.h"
#include "terrain/terrain_block.h"

using namespace planet;
namespace fs = std::filesystem;

namespace {

constexpr glm::ivec2 kSize{32, 18};

class FrameTest : public test::SharedRendererTest {
protected:
    static Session session(const std::string& view) { return loadSession(test::repoPaths(), "earth", view); }
};

}  // namespace

TEST(PassOrder, AReadBeforeAnyWriteIsReported) {
    using R = FrameResource;
    const std::vector<PassDeclaration> good{{"a", {}, {R::GBuffer}}, {"b", {R::GBuffer}, {R::HdrRadiance}}};
    EXPECT_TRUE(checkPassOrder(good).empty());
    const std::vector<PassDeclaration> bad{{"b", {R::GBuffer}, {R::HdrRadiance}}, {"a", {}, {R::GBuffer}}};
    const std::vector<std::string> problems = checkPassOrder(bad);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0], "pass 'b' reads G-buffer before any pass writes it");
}

TEST_F(FrameTest, TheRenderersPassesAreDeclaredInAnOrderThatHolds) {
    const std::vector<PassDeclaration> passes = renderer->passDeclarations();
    EXPECT_TRUE(checkPassOrder(passes).empty());
    std::vector<std::string> names;
    for (const PassDeclaration& p : passes) names.push_back(p.name);
    EXPECT_EQ(names, (std::vector<std::string>{"terrain", "terrain shadow", "surface light", "ocean", "terrain reflection",
                                              "sea reflection", "sky", "sky march", "sky temporal",
                                              "sky refine", "antialias", "tonemap", "ui"}));
}

TEST_F(FrameTest, BakedResourcesAreMadeInThePrepareStepOncePerChange) {
    Session s = session("orbit");
    s.scene.terrain.continent_map_size = 32;  // a quick bake
    renderer->render(s.scene, s.camera, kSize);
    const int loads = renderer->continents().loads();
    renderer->render(s.scene, s.camera, kSize);
    EXPECT_FALSE(renderer->lastPrepare().continentsUpdated);
    EXPECT_EQ(renderer->continents().loads(), loads);

    s.scene.terrain.seed += 17;  // a parameter of the bake
    renderer->render(s.scene, s.camera, kSize);
    EXPECT_TRUE(renderer->lastPrepare().continentsUpdated);
    EXPECT_EQ(renderer->continents().loads(), loads + 1);
    renderer->render(s.scene, s.camera, kSize);
    renderer->render(s.scene, s.camera, kSize);
    EXPECT_FALSE(renderer->lastPrepare().continentsUpdated);
    EXPECT_EQ(renderer->continents().loads(), loads + 1);  // once, not once per pass or per frame
    // The CPU copy and the GPU texture come from the same bake.
    ASSERT_TRUE(renderer->continents().map());
    EXPECT_EQ(renderer->continents().map()->size, 32);

    // The profiler shows the work under "prepare", before the passes; the passes themselves bake nothing.
    renderer->profiler().waitForResults();
    bool sawPrepare = false;
    for (const PassTimings& p : renderer->profiler().passes()) sawPrepare = sawPrepare || p.name == "prepare";
    EXPECT_TRUE(sawPrepare);
}

TEST_F(FrameTest, HistoryIsKeptForSmallMovesAndDroppedOnResizeJumpOrSceneChange) {
    Session s = session("beach");
    renderer->render(s.scene, s.camera, kSize);
    renderer->render(s.scene, s.camera, kSize);
    EXPECT_TRUE(renderer->lastPrepare().historyValid);
    const int index = renderer->frameIndex();

    s.camera.position += s.camera.forward() * 0.5;  // half a metre: the same place
    renderer->render(s.scene, s.camera, kSize);
    EXPECT_TRUE(renderer->lastPrepare().historyValid);
    EXPECT_EQ(renderer->frameIndex(), index + 1);

    renderer->render(s.scene, s.camera, {kSize.x + 2, kSize.y});
    EXPECT_FALSE(renderer->lastPrepare().historyValid) << "resize";
    renderer->render(s.scene, s.camera, {kSize.x + 2, kSize.y});
    EXPECT_TRUE(renderer->lastPrepare().historyValid);

    Session far = session("orbit");
    far.scene = s.scene;
    renderer->render(far.scene, far.camera, {kSize.x + 2, kSize.y});
    EXPECT_FALSE(renderer->lastPrepare().historyValid) << "jump";

    Session changed = far;
    changed.scene.atmosphere.mie_g = 0.5;
    renderer->render(far.scene, far.camera, {kSize.x + 2, kSize.y});
    EXPECT_TRUE(renderer->lastPrepare().historyValid);
    renderer->render(changed.scene, changed.camera, {kSize.x + 2, kSize.y});
    EXPECT_FALSE(renderer->lastPrepare().historyValid) << "scene change";
}

TEST(FrameUniformsTest, ReprojectionFindsAPointWhereThePreviousCameraSawIt) {
    // A point seen by two cameras 3 m apart on a beach, 6371 km from the planet centre: its
    // position relative to the new camera, through previousClipFromWorld and
    // cameraFromPrevious (float), lands where the previous camera projected it (double).
    Scene scene;
    Camera before;
    before.position = glm::dvec3(6371.0e3 + 2.0, 0.0, 0.0);
    before.orientation = orientationFromAxes({0, 1, 0}, {1, 0, 0}, glm::normalize(glm::dvec3(-0.05, 0.0, -1.0)));
    Camera now = before;
    now.position += glm::dvec3(0.0, 3.0, 0.0);
    const glm::ivec2 size{640, 360};
    const FrameUniforms u = makeFrameUniforms(scene, now, size, 5, PreviousFrame{before, size});
    EXPECT_EQ(u.historyValid, 1.0f);
    const glm::dvec3 world = before.position + glm::dvec3(-2.0, 1.0, -40.0);
    const glm::dvec4 clipBefore =
        before.clipFromView(double(size.x) / size.y) * glm::dvec4(glm::transpose(before.worldFromView()) * (world - before.position), 1.0);
    const glm::dvec3 expected = glm::dvec3(clipBefore) / clipBefore.w;
    const glm::vec3 relative(world - now.position);  // what a shader holds
    const glm::vec4 clip = u.previousClipFromWorld * glm::vec4(relative + u.cameraFromPrevious, 1.0f);
    const glm::vec3 got = glm::vec3(clip) / clip.w;
    EXPECT_NEAR(got.x, expected.x, 1e-5);
    EXPECT_NEAR(got.y, expected.y, 1e-5);
    EXPECT_NEAR(got.z, expected.z, 1e-6);
    // No history: the terms are the frame's own, and say so.
    const FrameUniforms first = makeFrameUniforms(scene, now, size, 0, std::nullopt);
    EXPECT_EQ(first.historyValid, 0.0f);
    EXPECT_EQ(first.cameraFromPrevious, glm::vec3(0.0f));
}

TEST(FrameUniformsTest, TheViewStandsStillWhileTheClockRunsAndToWithinRounding) {
    // The clock alone moved: the view stood still, the frame did not (the temporal march marks
    // only what its samples missed, render/sky_temporal.frag). A camera path between two equal
    // keyframes moves the camera by rounding errors, which count as standing still; a millimetre
    // or a few microradians of the camera or the sun do not.
    Scene scene;
    Camera camera;
    camera.position = glm::dvec3(6371.0e3 + 30.0, 0.0, 0.0);
    camera.orientation = orientationFromAxes({0, 1, 0}, {1, 0, 0}, glm::normalize(glm::dvec3(-0.05, 0.0, -1.0)));
    const glm::ivec2 size{64, 36};
    const glm::dvec3 sun = scene.sunDirection();
    const PreviousFrame before{camera, size, scene.time_s, sun};
    const FrameUniforms still = makeFrameUniforms(scene, camera, size, 1, before);
    EXPECT_EQ(still.stillSincePrevious, 1.0f);
    EXPECT_EQ(still.viewStillSincePrevious, 1.0f);
    Scene later = scene;
    later.time_s += 1.0 / 30.0;
    const FrameUniforms clock = makeFrameUniforms(later, camera, size, 1, before);
    EXPECT_EQ(clock.stillSincePrevious, 0.0f);
    EXPECT_EQ(clock.viewStillSincePrevious, 1.0f);
    // The explorer's anti-aliasing jitters the projection by a fraction of a pixel each frame:
    // the camera and the sun stood all the same.
    const FrameUniforms jittered = makeFrameUniforms(later, camera, size, 1, before, glm::dvec2(0.25, -0.125));
    EXPECT_EQ(jittered.viewStillSincePrevious, 1.0f);
    EXPECT_EQ(jittered.stillSincePrevious, 0.0f);  // the clock ran under the clouds
    const FrameUniforms jitteredOnly = makeFrameUniforms(scene, camera, size, 1, before, glm::dvec2(0.25, -0.125));
    EXPECT_EQ(jitteredOnly.viewStillSincePrevious, 1.0f);
    EXPECT_EQ(jitteredOnly.stillSincePrevious, 1.0f);  // only the jitter moved: a still frame

    Camera rounded = camera;
    rounded.position += glm::dvec3(1.0e-6, -2.0e-6, 0.0);
    rounded.orientation = glm::normalize(rounded.orientation + glm::dquat(0.0, 1.0e-12, 0.0, 0.0));
    EXPECT_TRUE(viewStoodStill(camera, rounded, sun, sun));
    Camera moved = camera;
    moved.position += glm::dvec3(0.0, 2.0e-3, 0.0);
    EXPECT_FALSE(viewStoodStill(camera, moved, sun, sun));
    EXPECT_EQ(makeFrameUniforms(later, moved, size, 1, before).viewStillSincePrevious, 0.0f);
    Camera turned = camera;
    turned.orientation = glm::angleAxis(5.0e-6, glm::dvec3(0.0, 0.0, 1.0)) * turned.orientation;
    EXPECT_FALSE(viewStoodStill(camera, turned, sun, sun));
    const glm::dvec3 sunMoved = glm::angleAxis(5.0e-6, glm::dvec3(0.0, 0.0, 1.0)) * sun;
    EXPECT_FALSE(viewStoodStill(camera, camera, sun, sunMoved));
    EXPECT_TRUE(viewStoodStill(camera, camera, sun, glm::angleAxis(1.0e-8, glm::dvec3(0.0, 0.0, 1.0)) * sun));
}

TEST(FrameUniformsTest, FromHighAboveTheCloudsTheClockMovesNothingAPixelCanShow) {
    // The wind moves the clouds wind_speed_mps a second; seen from 400 km up with 60 degrees over
    // 720 pixels, 10 m/s at 30 Hz is 0.333 m / 396 km / (pi / 3 / 720) = 5.8e-4 pixels a frame
    // at the layer's top (4 km), under kStillCloudDriftPx: the frame counts as still (the
    // reconstruction's still program). From 10 km up (6 km above the tops) 0.038, and from
    // under the layer any drift may cross a pixel: the clock moves the frame.
    Scene scene;
    const glm::ivec2 size{1280, 720};
    const double radius = scene.planetRadiusM();
    Camera camera;
    camera.fovY_rad = glm::radians(60.0);
    camera.orientation = orientationFromAxes({0, 1, 0}, {0, 0, 1}, {-1, 0, 0});  // looking down
    camera.position = glm::dvec3(radius + 400.0e3, 0.0, 0.0);
    scene.clouds.wind_speed_mps = 10.0;
    const double frame_s = 1.0 / 30.0;
    const double expected = 10.0 * frame_s / (400.0e3 - scene.clouds.top_altitude_km * 1000.0) / (glm::radians(60.0) / 720.0);
    EXPECT_NEAR(cloudDriftPixels(scene, camera, size, frame_s), expected, 1e-9);
    EXPECT_NEAR(expected, 5.8e-4, 0.1e-4);
    const glm::dvec3 sun = scene.sunDirection();
    const PreviousFrame before{camera, size, scene.time_s, sun};
    Scene later = scene;
    later.time_s += frame_s;
    EXPECT_EQ(makeFrameUniforms(later, camera, size, 1, before).stillSincePrevious, 1.0f) << "orbit";

    Camera aircraft = camera;
    aircraft.position = glm::dvec3(radius + 10.0e3, 0.0, 0.0);
    EXPECT_NEAR(cloudDriftPixels(scene, aircraft, size, frame_s), 0.038, 0.001);
    const PreviousFrame beforeAircraft{aircraft, size, scene.time_s, sun};
    EXPECT_EQ(makeFrameUniforms(later, aircraft, size, 1, beforeAircraft).stillSincePrevious, 0.0f) << "aircraft";

    Camera under = camera;
    under.position = glm::dvec3(radius + 30.0, 0.0, 0.0);
    EXPECT_TRUE(std::isinf(cloudDriftPixels(scene, under, size, frame_s)));
    const PreviousFrame beforeUnder{under, size, scene.time_s, sun};
    EXPECT_EQ(makeFrameUniforms(later, under, size, 1, beforeUnder).stillSincePrevious, 0.0f) << "under the clouds";
    // No wind, or no clouds: the clock moves nothing in the sky, wherever the camera is.
    Scene calm = later;
    calm.clouds.wind_speed_mps = 0.0;
    EXPECT_EQ(makeFrameUniforms(calm, under, size, 1, beforeUnder).stillSincePrevious, 1.0f) << "no wind";
    Scene clear = later;
    clear.clouds.enabled = false;
    EXPECT_EQ(makeFrameUniforms(clear, under, size, 1, beforeUnder).stillSincePrevious, 1.0f) << "no clouds";
}

TEST(FrameUniformsTest, JitterIsAHaltonSequenceInsideThePixel) {
    EXPECT_DOUBLE_EQ(halton(1, 2), 0.5);
    EXPECT_DOUBLE_EQ(halton(2, 2), 0.25);
    EXPECT_DOUBLE_EQ(halton(3, 2), 0.75);
    EXPECT_DOUBLE_EQ(halton(1, 3), 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(halton(4, 3), 1.0 / 3.0 + 1.0 / 9.0);
    std::set<std::pair<float, float>> seen;
    glm::vec2 mean(0.0f);
    for (int i = 0; i < 16; ++i) {
        const glm::vec2 j = subPixelJitter(i);
        EXPECT_GE(j.x, -0.5f);
        EXPECT_LT(j.x, 0.5f);
        EXPECT_GE(j.y, -0.5f);
        EXPECT_LT(j.y, 0.5f);
        seen.insert({j.x, j.y});
        mean += j / 16.0f;
    }
    EXPECT_EQ(seen.size(), 16u);
    EXPECT_LT(std::abs(mean.x), 0.05f);  // well spread: centred on the pixel
    EXPECT_LT(std::abs(mean.y), 0.1f);
    // Every cycle of 16 frames takes the 16 elements (the anti-aliasing's), and the frames 16
    // apart (when the reduced-rate march traces a pixel again: render/sparse_pattern.glsl) take
    // each of them in turn, so that a pixel's visits sample its whole area.
    for (int start : {16, 48, 5 * 16}) {
        std::set<std::pair<float, float>> cycle, visits;
        for (int i = 0; i < 16; ++i) {
            const glm::vec2 j = subPixelJitter(start + i), v = subPixelJitter(start + 3 + 16 * i);
            cycle.insert({j.x, j.y});
            visits.insert({v.x, v.y});
        }
        EXPECT_EQ(cycle, seen);
        EXPECT_EQ(visits, seen);
    }
}

TEST(FrameUniformsTest, TheViewsSidePlanesPassThroughTheFramesEdges) {
    // Points on the rays through the middles of the frame's four edges lie on one plane each (and
    // inside the other three); the frame's centre lies inside all four, a point past the right edge
    // outside that edge's plane alone. A plane off by a row or column of the matrix, or not
    // normalised, breaks these (ocean/grid_reflection.comp culls by them, in metres).
    Camera camera;
    camera.position = glm::dvec3(6371.0e3 + 1500.0, 200.0, -300.0);
    camera.orientation = orientationFromAxes({0, 1, 0}, {1, 0, 0}, glm::normalize(glm::dvec3(0.2, 0.1, -1.0)));
    const glm::ivec2 size{64, 36};
    const FrameUniforms u = makeFrameUniforms(Scene{}, camera, size, 3, std::nullopt, glm::dvec2(0.25, -0.375));
    const glm::dmat4 viewFromClip(u.viewFromClip);
    auto pointAt = [&](glm::dvec2 ndc, double distance) {  // camera-relative, world axes
        const glm::dvec4 view = viewFromClip * glm::dvec4(ndc, 0.5, 1.0);
        return distance * glm::normalize(camera.worldFromView() * (glm::dvec3(view) / view.w));
    };
    auto inside = [&](int k, glm::dvec3 p) { return glm::dot(glm::dvec3(u.viewSidePlanes[k]), p) + u.viewSidePlanes[k].w; };
    const glm::dvec2 edges[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};  // x = -w, x = w, y = -w, y = w
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(glm::length(glm::dvec3(u.viewSidePlanes[k])), 1.0, 1e-6);
        for (double d : {10.0, 5000.0}) {
            const glm::dvec3 p = pointAt(edges[k], d);
            EXPECT_NEAR(inside(k, p), 0.0, 1e-5 * d) << "plane " << k << " at " << d << " m";
            for (int other = 0; other < 4; ++other) {
                if (other == k) continue;
                EXPECT_GT(inside(other, p), 0.1 * d) << "plane " << other << " at edge " << k;
            }
            EXPECT_GT(inside(k, pointAt(glm::dvec2(0.0), d)), 0.1 * d);
        }
    }
    const glm::dvec3 pastRight = pointAt({1.2, 0.0}, 1000.0);
    EXPECT_LT(inside(1, pastRight), -10.0);
    EXPECT_GT(inside(0, pastRight), 0.0);
}

namespace {

// A block's binding, size and the offsets of some members, as the driver laid them out.
struct BlockLayout {
    GLint binding = -1, size = -1;
};
BlockLayout blockLayout(GLuint program, const char* name) {
    const GLuint index = glGetUniformBlockIndex(program, name);
    BlockLayout l;
    if (index == GL_INVALID_INDEX) return l;
    glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_BINDING, &l.binding);
    glGetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_DATA_SIZE, &l.size);
    return l;
}
GLint memberOffset(GLuint program, const char* name) {
    GLuint index = GL_INVALID_INDEX;
    glGetUniformIndices(program, 1, &name, &index);
    if (index == GL_INVALID_INDEX) return -1;
    GLint offset = -1;
    glGetActiveUniformsiv(program, 1, &index, GL_UNIFORM_OFFSET, &offset);
    return offset;
}

}  // namespace

TEST_F(FrameTest, BlockMirrorsMatchTheDriversLayoutAndBindings) {
    // Programs that declare every block (the ocean's mesh and its light read all six between
    // them); std140 is what the C++ static_asserts assume, and this asks the driver itself.
    const gl::ShaderSources sources{test::repoPaths().shaders(),
                                    gl::shaderPreamble() +
                                        atmosphere::atmosphereShaderDefines(atmosphere::TableSizes::reduced())};
    const gl::Program ocean = gl::buildProgram(
        sources, {"ocean", {"ocean/ocean.vert", "ocean/ocean.tesc", "ocean/ocean.tese", "ocean/ocean.frag"}});
    const GLuint p = ocean.id();
    const BlockLayout frame = blockLayout(p, "FrameBlock");
    EXPECT_EQ(frame.binding, binding::BLOCK_FRAME);
    EXPECT_EQ(frame.size, static_cast<GLint>(sizeof(FrameUniforms)));
    EXPECT_EQ(memberOffset(p, "FrameBlock.cameraDepthBelowSea"), static_cast<GLint>(offsetof(FrameUniforms, cameraDepthBelowSea)));
    EXPECT_EQ(memberOffset(p, "FrameBlock.nearPlane"), static_cast<GLint>(offsetof(FrameUniforms, nearPlane)));
    EXPECT_EQ(memberOffset(p, "FrameBlock.viewSidePlanes[0]"), static_cast<GLint>(offsetof(FrameUniforms, viewSidePlanes)));
    const gl::Program seaLight = gl::buildProgram(sources, {"sea light", {"common/fullscreen.vert", "ocean/sea_light.frag"}});
    const BlockLayout atmosphereBlock = blockLayout(seaLight.id(), "AtmosphereBlock");
    EXPECT_EQ(atmosphereBlock.binding, binding::BLOCK_ATMOSPHERE);
    EXPECT_EQ(atmosphereBlock.size, static_cast<GLint>(sizeof(atmosphere::AtmosphereUniforms)));
    EXPECT_EQ(memberOffset(seaLight.id(), "AtmosphereBlock.muSMin"),
              static_cast<GLint>(offsetof(atmosphere::AtmosphereUniforms, muSMin)));
    const BlockLayout terrainBlock = blockLayout(p, "TerrainBlock");
    EXPECT_EQ(terrainBlock.binding, binding::BLOCK_TERRAIN);
    EXPECT_EQ(terrainBlock.size, static_cast<GLint>(sizeof(terrain::TerrainBlock)));
    const gl::Program terrainProgram = gl::buildProgram(
        sources, {"terrain", {"terrain/terrain.vert", "terrain/terrain.tesc", "terrain/terrain.tese", "terrain/terrain.frag"}});
    EXPECT_EQ(memberOffset(terrainProgram.id(), "terrainDarkFloorCulling"),
              static_cast<GLint>(offsetof(terrain::TerrainBlock, darkFloorCulling)));
    const BlockLayout oceanBlock = blockLayout(p, "OceanBlock");
    EXPECT_EQ(oceanBlock.binding, binding::BLOCK_OCEAN);
    EXPECT_EQ(oceanBlock.size, static_cast<GLint>(sizeof(ocean::OceanBlock)));
    EXPECT_EQ(memberOffset(p, "OceanBlock.waveCount"), static_cast<GLint>(offsetof(ocean::OceanBlock, waveCount)));
    EXPECT_EQ(memberOffset(p, "OceanBlock.continentSampleSlackRad"),
              static_cast<GLint>(offsetof(ocean::OceanBlock, continentSampleSlackRad)));
    const BlockLayout grid = blockLayout(p, "GridBlock");
    EXPECT_EQ(grid.binding, binding::BLOCK_GRID);
    EXPECT_EQ(grid.size, static_cast<GLint>(sizeof(GridBlock)));
    EXPECT_EQ(memberOffset(p, "GridBlock.exponent"), static_cast<GLint>(offsetof(GridBlock, exponent)));
    EXPECT_EQ(memberOffset(p, "GridBlock.pointsPerSide"), static_cast<GLint>(offsetof(GridBlock, pointsPerSide)));
    EXPECT_EQ(memberOffset(p, "GridBlock.stride"), static_cast<GLint>(offsetof(GridBlock, stride)));
    const gl::Program nearGrid = gl::buildProgram(sources, {"near grid", {"terrain/near_height_grid.comp"}});
    const BlockLayout nearGridBlock = blockLayout(nearGrid.id(), "NearHeightGridBlock");
    EXPECT_EQ(nearGridBlock.binding, binding::BLOCK_TERRAIN_NEAR_GRID);
    EXPECT_EQ(nearGridBlock.size, static_cast<GLint>(sizeof(terrain::NearHeightGridBlock)));
    EXPECT_EQ(memberOffset(nearGrid.id(), "nearGridNorth"), static_cast<GLint>(offsetof(terrain::NearHeightGridBlock, north)));
}

TEST(FrameSources, AerialPerspectiveIsComputedInOneShaderFunctionCalledFromOnePass) {
    // Every shader under shaders/ (the atmosphere's own model files aside): only the unified
    // march of clouds and atmosphere (clouds/cloud_march.glsl, MarchView / MarchViewAt) calls the
    // interface's SkyRadianceToPoint(At), nothing outside the interface calls the model's
    // in-scattering lookups, and the only passes that march to a surface point are the sky
    // passes, through one function (render/sky_air.glsl, marchAir: at full rate and at the
    // reduced rate); the ocean marches its reflected rays to space (ocean/cloud_reflection.glsl: no surface, no aerial
    // perspective), except where its screen-space reflection finds land: the air along the
    // reflected ray from the water to that land is the one other aerial perspective
    // (ocean/screen_space_reflections.glsl).
    // Probes (compute shaders that run the same functions for tests) may call anything.
    const fs::path root = test::repoPaths().shaders();
    const std::regex toPoint(R"(\bSkyRadianceToPoint(At|OfRay)?\s*\()");
    const std::regex model(R"(\bGetSkyRadianceToPoint\w*\s*\()");
    const std::regex march(R"(\bMarchView(At)?\s*\()");  // At: the viewpoint by its up and altitude
    std::vector<std::string> toPointCallers, marchCallers;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file()) continue;
        const std::string rel = fs::relative(entry.path(), root).generic_string();
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string source = text.str();
        if (rel == "atmosphere/interface.glsl" || rel == "atmosphere/rendering.glsl" || rel == "atmosphere/elek_table.glsl")
            continue;
        if (std::regex_search(source, toPoint)) toPointCallers.push_back(rel);
        if (std::regex_search(source, march) && rel != "clouds/cloud_march.glsl") marchCallers.push_back(rel);
        EXPECT_FALSE(std::regex_search(source, model)) << rel << " calls the model's aerial perspective directly";
    }
    std::sort(toPointCallers.begin(), toPointCallers.end());
    EXPECT_EQ(toPointCallers,
              (std::vector<std::string>{"clouds/cloud_march.glsl", "ocean/screen_space_reflections.glsl"}));
    std::sort(marchCallers.begin(), marchCallers.end());
    for (const std::string& caller : marchCallers)
        EXPECT_TRUE(caller == "render/sky_air.glsl" || caller == "ocean/cloud_reflection.glsl" || caller.ends_with("_probe.comp"))
            << caller;
    EXPECT_NE(std::find(marchCallers.begin(), marchCallers.end(), "render/sky_air.glsl"), marchCallers.end());
}
