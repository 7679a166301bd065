// Headless renders of the placeholder planet through the whole frame
// (terrain -> lighting -> tonemap), checked for what they must show.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/session.h"
#include "gl_test_support.h"
#include "grid/projected_grid.h"
#include "render/image_io.h"
#include "render/renderer.h"
#include "terrain/height.h"
#include "shaders_ray_sphere_double.h"

using namespace planet;

namespace {

constexpr glm::ivec2 kSize{160, 90};

class RenderTest : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    Session session(const std::string& preset, const std::string& view) {
        return loadSession(test::repoPaths(), preset, view);
    }
    ImageRGBAF renderHdr(const Session& s, glm::ivec2 size = kSize) {
        renderer->render(s.scene, s.camera, size);
        return readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
    }
    std::unique_ptr<Renderer> renderer;
};

float luminance(const float* p) { return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]; }

}  // namespace

TEST_F(RenderTest, SpaceViewShowsPlanetInTheCentreAndDarkSpaceAround) {
    const Session s = session("earth", "space");
    const ImageRGBAF hdr = renderHdr(s);
    ASSERT_TRUE(test::allFinite(hdr));
    // The whole planet is in view: all four corners are space (zero radiance).
    for (auto [x, y] : {std::pair{0, 0}, {kSize.x - 1, 0}, {0, kSize.y - 1}, {kSize.x - 1, kSize.y - 1}})
        EXPECT_EQ(luminance(test::pixelAt(hdr, x, y)), 0.0f) << x << "," << y;
    // The centre pixel is covered by the planet (G-buffer material = ground, depth in (0, 1)).
    float depth = 0.0f;
    glGetTextureSubImage(renderer->targets().gbuffer().depth.id(), 0, kSize.x / 2, kSize.y / 2, 0, 1, 1, 1,
                         GL_DEPTH_COMPONENT, GL_FLOAT, sizeof depth, &depth);
    EXPECT_GT(depth, 0.0f);
    EXPECT_LT(depth, 1.0f);
}

TEST_F(RenderTest, OrbitViewIsLitBelowAndSpaceAbove) {
    const Session s = session("earth", "orbit");
    const ImageRGBAF hdr = renderHdr(s);
    ASSERT_TRUE(test::allFinite(hdr));
    EXPECT_GT(luminance(test::pixelAt(hdr, kSize.x / 2, kSize.y - 1)), 1e-3f);  // ground below: lit
    EXPECT_EQ(luminance(test::pixelAt(hdr, kSize.x / 2, 0)), 0.0f);               // space above the horizon
}

TEST_F(RenderTest, GroundDepthMatchesCpuRaySphereDistance) {
    // From 2 m above flat terrain, the G-buffer depth of a pixel below the
    // horizon must decode to the distance the double-precision ray-sphere
    // intersection gives along that pixel's ray (GPU vs CPU reference): the
    // projected grid, its tessellation and the depth setup together.
    Session s = session("earth", "ground");
    s.scene.terrain.max_height_m = s.scene.terrain.ocean_depth_m = 0.0;  // flat: the terrain is the sphere
    renderer->render(s.scene, s.camera, kSize);
    const int x = kSize.x / 2, y = 2;  // near the bottom edge (GL row 2), looking down at the ground
    float depth = 0.0f;
    glGetTextureSubImage(renderer->targets().gbuffer().depth.id(), 0, x, y, 0, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                         sizeof depth, &depth);
    ASSERT_GT(depth, 0.0f);
    const double aspect = double(kSize.x) / kSize.y;
    const glm::dvec2 ndc((x + 0.5) / kSize.x * 2 - 1, (y + 0.5) / kSize.y * 2 - 1);
    const glm::dvec4 v = glm::inverse(s.camera.clipFromView(aspect)) * glm::dvec4(ndc, 0.5, 1.0);
    const glm::dvec3 viewDir = glm::normalize(glm::dvec3(v) / v.w);
    const glm::dvec3 worldDir = s.camera.worldFromView() * viewDir;
    const double R = s.scene.planetRadiusM();
    const double t = test::nearestHitDouble(s.camera.position, worldDir, R);
    ASSERT_GT(t, 0.0);
    const double expectedViewDistance = t * -viewDir.z;
    const double gpuViewDistance = viewZFromDepth(depth, s.camera.near_m) * -1.0;
    EXPECT_NEAR(gpuViewDistance, expectedViewDistance, expectedViewDistance * 1e-3);
}

TEST_F(RenderTest, SameInputsGiveSamePixels) {
    const Session s = session("earth", "orbit");
    renderer->render(s.scene, s.camera, kSize);
    const ImageRGBA8 a = readTextureRGBA8(renderer->targets().ldr(), kSize.x, kSize.y);
    Renderer other(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    other.render(s.scene, s.camera, kSize);
    const ImageRGBA8 b = readTextureRGBA8(other.targets().ldr(), kSize.x, kSize.y);
    EXPECT_EQ(a.pixels, b.pixels);
}

TEST_F(RenderTest, EveryPresetAndViewRendersWithoutNanOrInf) {
    for (const std::string preset : {"earth", "mars", "hazy"}) {
        Session s = session(preset, "orbit");
        for (const View& view : s.views) {
            applyView(view, s);
            const ImageRGBAF hdr = renderHdr(s, {64, 36});
            EXPECT_TRUE(test::allFinite(hdr)) << preset << " / " << view.name;
        }
    }
}

TEST_F(RenderTest, ExtremeCamerasAreHandled) {
    Session s = session("earth", "orbit");
    const double R = s.scene.planetRadiusM();
    for (double distance : {0.5 * R, R + 0.1, R + 1.0, 2.0e8, 9.46e15}) {
        s.camera.position = glm::dvec3(0.0, 0.0, distance);
        sanitizeCamera(s.camera, R);
        EXPECT_GE(s.camera.altitude(R), 0.09);
        EXPECT_TRUE(test::allFinite(renderHdr(s, {32, 18}))) << distance;
    }
}

TEST_F(RenderTest, TargetsCarryDebugLabels) {
    const Session s = session("earth", "orbit");
    renderer->render(s.scene, s.camera, kSize);
    char label[64] = {};
    GLsizei length = 0;
    glGetObjectLabel(GL_TEXTURE, renderer->targets().hdr().id(), sizeof label, &length, label);
    EXPECT_STREQ(label, "hdr");
    glGetObjectLabel(GL_FRAMEBUFFER, renderer->targets().gbuffer().framebuffer.id(), sizeof label, &length, label);
    EXPECT_STREQ(label, "gbuffer");
}

TEST_F(RenderTest, ViewWithoutSunKeysRestoresThePresetSun) {
    Session s = session("earth", "orbit");  // orbit places the sun
    ASSERT_NE(s.scene.sun.latitude_deg, s.presetScene.sun.latitude_deg);
    View plain = s.view;
    plain.sun_elevation_deg.reset();
    plain.sun_azimuth_deg.reset();
    applyView(plain, s);
    EXPECT_EQ(s.scene.sun.latitude_deg, s.presetScene.sun.latitude_deg);
    EXPECT_EQ(s.scene.sun.longitude_deg, s.presetScene.sun.longitude_deg);
}

TEST_F(RenderTest, CameraAtThePlanetCentreGivesNoNan) {
    Session s = session("earth", "orbit");
    s.camera.position = glm::dvec3(0.0);  // unsanitised: the renderer itself must stay finite
    EXPECT_TRUE(test::allFinite(renderHdr(s, {32, 18})));
}

TEST_F(RenderTest, ZeroSizeRendersNothingAndKeepsTargets) {
    const Session s = session("earth", "orbit");
    renderer->render(s.scene, s.camera, kSize);
    renderer->render(s.scene, s.camera, {0, 0});
    EXPECT_EQ(renderer->targets().size(), kSize);
}

TEST_F(RenderTest, ProfilerTimesEveryPassOnTheGpuAndCpu) {
    // A renderer of its own (the shared one's profiler holds other tests' passes), marching at
    // full rate (the temporal march's passes are timed in tests/test_temporal.cpp's bench).
    Session s = session("earth", "orbit");
    s.scene.render.temporal = false;
    Renderer own(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    for (int i = 0; i < 6; ++i) own.render(s.scene, s.camera, {32, 18});
    own.profiler().waitForResults();
    std::vector<std::string> names;
    for (const PassTimings& p : own.profiler().passes()) {
        names.push_back(p.name);
        EXPECT_EQ(p.cpuMs.size(), 6u) << p.name;
        EXPECT_GE(p.gpuMs.size(), 2u) << p.name;  // the ring may drop frames on a slow GPU, never all
        EXPECT_GE(p.gpuMs.min(), 0.0) << p.name;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"prepare", "terrain", "terrain shadow", "surface light", "ocean", "terrain reflection", "sky",
                                              "tonemap"}));
}

TEST_F(RenderTest, TerrainLeavesNoHolesWhereTheGroundMustBe) {
    // Every pixel whose ray hits the sea-level sphere must hold a surface, the terrain or
    // the sea over it (depth written); with the ocean off, every pixel whose ray hits the
    // sphere of the deepest sea floor must hold terrain. A hole means a projected grid
    // missed part of the visible planet (Michelic §3 coverage) or culling dropped a
    // visible patch.
    for (const bool ocean : {true, false}) {
        for (const std::string view : {"ground", "beach", "aircraft", "orbit", "space"}) {
            Session s = session("earth", view);
            s.scene.terrain.ocean = ocean;
            renderer->render(s.scene, s.camera, kSize);
            std::vector<float> depth(static_cast<std::size_t>(kSize.x) * kSize.y);
            glGetTextureImage(renderer->targets().gbuffer().depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                              static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
            const double floor = s.scene.planetRadiusM() - (ocean ? 0.0 : s.scene.terrain.ocean_depth_m);
            const glm::dmat4 viewFromClip = glm::inverse(s.camera.clipFromView(double(kSize.x) / kSize.y));
            int mustBeGround = 0, holes = 0;
            for (int y = 0; y < kSize.y; ++y) {
                for (int x = 0; x < kSize.x; ++x) {
                    const glm::dvec2 ndc((x + 0.5) / kSize.x * 2 - 1, (y + 0.5) / kSize.y * 2 - 1);
                    const glm::dvec4 v = viewFromClip * glm::dvec4(ndc, 0.5, 1.0);
                    const glm::dvec3 dir = s.camera.worldFromView() * glm::normalize(glm::dvec3(v) / v.w);
                    // Skip rays within a pixel of grazing the sphere, where rasterisation decides.
                    const double t = test::nearestHitDouble(s.camera.position, dir, floor - 50.0);
                    if (t < 0.0) continue;
                    ++mustBeGround;
                    holes += depth[static_cast<std::size_t>(y) * kSize.x + x] == 0.0f;
                }
            }
            EXPECT_GT(mustBeGround, 0) << view;
            EXPECT_EQ(holes, 0) << view << (ocean ? " (sea)" : " (dry)") << ": " << holes << " of " << mustBeGround
                                << " ground pixels empty";
        }
    }
}

namespace {

// CPU reference of a terrain silhouette: does the ray hit the terrain (or the
// sea surface)? Marched in double with the shared height function, in steps
// that grow with distance (0.1 % of it, at least 10 m).
bool rayHitsGround(const Scene& scene, const terrain::HeightField& ground, const glm::dvec3& origin,
                   const glm::dvec3& dir) {
    const double radius = scene.planetRadiusM();
    const double ceiling = radius + scene.terrain.max_height_m;
    for (double t = 1.0; t < 2.0e6; t += std::max(10.0, 1e-3 * t)) {
        const glm::dvec3 p = origin + dir * t;
        const double r = glm::length(p);
        if (r > ceiling && glm::dot(p, dir) > 0.0) return false;  // above every peak and climbing
        if (r <= radius + terrain::surfaceHeightM(ground, p)) return true;
    }
    return false;
}

}  // namespace

TEST_F(RenderTest, MountainSilhouetteMatchesTheCpuHeightField) {
    // A range seen across 100-200 km: the GPU terrain's silhouette (first
    // covered row from the top, per column) agrees with the CPU height field
    // within 2 rows, and stands above the sea-level horizon, so peaks beyond
    // the geometric horizon are drawn and not culled.
    const Session s = session("earth", "mountains");
    renderer->render(s.scene, s.camera, kSize);
    std::vector<std::uint8_t> material(static_cast<std::size_t>(kSize.x) * kSize.y * 4);
    glGetTextureImage(renderer->targets().gbuffer().material.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                      static_cast<GLsizei>(material.size()), material.data());
    const glm::dmat4 viewFromClip = glm::inverse(s.camera.clipFromView(double(kSize.x) / kSize.y));
    auto rayAt = [&](int x, int glRow) {
        const glm::dvec2 ndc((x + 0.5) / kSize.x * 2 - 1, (glRow + 0.5) / kSize.y * 2 - 1);
        const glm::dvec4 v = viewFromClip * glm::dvec4(ndc, 0.5, 1.0);
        return glm::normalize(s.camera.worldFromView() * glm::normalize(glm::dvec3(v) / v.w));
    };
    int agreeing = 0, aboveSeaHorizon = 0, columns = 0;
    for (int x = 2; x < kSize.x; x += 6) {
        int silhouette = -1;  // highest covered GL row (GL row 0 is the bottom)
        for (int y = kSize.y - 1; y >= 0 && silhouette < 0; --y)
            if (material[(static_cast<std::size_t>(y) * kSize.x + x) * 4] != 0) silhouette = y;
        if (silhouette < 2 || silhouette > kSize.y - 3) continue;
        ++columns;
        const bool hitBelow = rayHitsGround(s.scene, s.ground, s.camera.position, rayAt(x, silhouette - 2));
        const bool missAbove = !rayHitsGround(s.scene, s.ground, s.camera.position, rayAt(x, silhouette + 2));
        agreeing += hitBelow && missAbove;
        aboveSeaHorizon += test::nearestHitDouble(s.camera.position, rayAt(x, silhouette), s.scene.planetRadiusM()) < 0;
    }
    std::printf("silhouette: %d of %d columns agree with the CPU march\n", agreeing, columns);
    ASSERT_GT(columns, 20);
    EXPECT_GE(agreeing, columns * 9 / 10) << agreeing << " of " << columns;
    EXPECT_EQ(aboveSeaHorizon, columns);
}

TEST_F(RenderTest, CameraIsKeptAboveTheTerrainNotJustTheSphere) {
    Session s = session("earth", "ground");  // on land, about 430 m up
    const double ground = terrain::surfaceHeightM(s.ground, s.camera.position);
    ASSERT_GT(ground, 100.0);
    EXPECT_NEAR(s.camera.altitude(s.scene.planetRadiusM()), ground + 2.0, 1e-3);  // the view stands 2 m up
    s.camera.position = glm::normalize(s.camera.position) * (s.scene.planetRadiusM() + 10.0);  // inside the hill
    EXPECT_TRUE(keepAboveGround(s));
    EXPECT_NEAR(s.camera.altitude(s.scene.planetRadiusM()), ground + kCameraMinAltitudeM, 1e-3);
    EXPECT_FALSE(keepAboveGround(s));  // already above: unchanged
}

TEST_F(RenderTest, AnchorUpdatesDoNotPopVisibly) {
    // When the camera has moved just under the hysteresis threshold, the grids are still
    // projected from the old anchor; a renderer that starts afresh there projects them from
    // the camera itself. The two frames show the same camera with the two meshes an anchor
    // update switches between: they must look the same (the jump a user could see).
    for (const std::string view : {"ground", "beach", "aircraft", "orbit"}) {
        Session s = session("earth", view);
        s.scene.render.temporal = false;  // the meshes' difference, not the temporal march's
        s.scene.terrain.detail = true;    // which must not move with the mesh either
        const glm::ivec2 size{320, 180};
        renderer->render(s.scene, s.camera, size);  // anchors at the view's camera
        const double threshold = anchorThresholdM(GridParams{}, s.camera.altitude(s.scene.planetRadiusM()));
        const glm::dvec3 up = glm::normalize(s.camera.position);
        const glm::dvec3 sideways = glm::normalize(glm::cross(up, glm::dvec3(0.0, 0.0, 1.0)));
        s.camera.position += sideways * (0.9 * threshold);
        keepAboveGround(s);
        renderer->render(s.scene, s.camera, size);
        const ImageRGBAF stale = readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
        Renderer fresh(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
        fresh.render(s.scene, s.camera, size);
        const ImageRGBAF moved = readTextureRGBAF(fresh.targets().hdr(), size.x, size.y);
        int changed = 0, pixels = size.x * size.y;
        for (int i = 0; i < pixels; ++i) {
            const float a = luminance(&stale.pixels[4 * i]), b = luminance(&moved.pixels[4 * i]);
            changed += std::abs(a - b) > 0.05f * std::max(a, b) + 1e-4f;
        }
        std::printf("%s: an anchor update changes %d of %d pixels by more than 5 %%\n", view.c_str(), changed, pixels);
        if (changed >= pixels / 200) {  // the two frames, to be looked at with planet compare
            const auto dir = std::filesystem::temp_directory_path();
            writeExr(stale, dir / ("anchor_" + view + "_stale.exr"), 0.0);
            writeExr(moved, dir / ("anchor_" + view + "_fresh.exr"), 0.0);
            std::printf("  written: %s/anchor_%s_{stale,fresh}.exr\n", dir.c_str(), view.c_str());
        }
        EXPECT_LT(changed, pixels / 200) << view;  // 0.5 %: the odd silhouette or shoreline pixel
    }
}
