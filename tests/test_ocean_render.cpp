// Headless renders of the sea through the whole frame (terrain -> atmosphere -> ocean ->
// tonemap): no NaN anywhere, the sun's glitter where the sun reflects, a submerged camera
// handled, and the wave set's changes reaching the next frame.
#include <algorithm>
#include <cmath>

#include "app/session.h"
#include "gl_test_support.h"
#include "shaders_ray_sphere_double.h"
#include "ocean/ocean_pass.h"
#include "ocean/wave_spectrum.h"
#include "render/frame_uniforms.h"
#include "render/renderer.h"

using namespace planet;

namespace {

constexpr glm::ivec2 kSize{160, 90};

float luminance(const float* p) { return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]; }

// The pixel in GL row glRow (0 at the bottom; read-back images start at the top row).
const float* at(const ImageRGBAF& image, int x, int glRow) { return test::pixelAt(image, x, image.height - 1 - glRow); }

class OceanRender : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    }
    Session session(const std::string& view) { return loadSession(test::repoPaths(), "earth", view); }
    ImageRGBAF renderHdr(const Session& s, glm::ivec2 size = kSize) {
        renderer->render(s.scene, s.camera, size);
        return readTextureRGBAF(renderer->targets().hdr(), size.x, size.y);
    }
    // A view over deep water (the first point of a coarse lat/lon scan with the sea floor
    // below -2000 m), `altitude` above the sea, looking along `heading` at `pitch`, the sun
    // at `sunElevation` in the same azimuth.
    Session openSea(double altitude, double pitch, double sunElevation) {
        Session s = session("beach");
        s.scene.clouds.enabled = false;  // the sun's glitter, unshadowed
        for (double lat = -50.0; lat <= 50.0; lat += 2.5) {
            for (double lon = -180.0; lon < 180.0; lon += 2.5) {
                if (s.ground.height(glm::vec3(directionFromLatLon(lat, lon))) > -2000.0f) continue;
                View v;
                v.name = "open sea";
                v.latitude_deg = lat;
                v.longitude_deg = lon;
                v.altitude_m = altitude;
                v.heading_deg = 90.0;
                v.pitch_deg = pitch;
                v.sun_elevation_deg = sunElevation;
                v.sun_azimuth_deg = 90.0;
                applyView(v, s);
                std::printf("open sea at %.1f, %.1f\n", lat, lon);
                return s;
            }
        }
        ADD_FAILURE() << "no deep sea found";
        return s;
    }
    std::unique_ptr<Renderer> renderer;
};

}  // namespace

TEST_F(OceanRender, SeaViewsRenderWithoutNanAndRunTheOceanPass) {
    for (const std::string view : {"beach", "sunset", "sea", "orbit", "space"}) {
        const Session s = session(view);
        const ImageRGBAF hdr = renderHdr(s);
        EXPECT_TRUE(test::allFinite(hdr)) << view;
        float brightest = 0.0f;
        for (std::size_t i = 0; i + 3 < hdr.pixels.size(); i += 4) brightest = std::max(brightest, hdr.pixels[i + 1]);
        EXPECT_GT(brightest, 0.0f) << view << ": black frame";
    }
    std::vector<std::string> names;
    for (const PassTimings& p : renderer->profiler().passes()) names.push_back(p.name);
    EXPECT_NE(std::find(names.begin(), names.end(), "ocean"), names.end());
}

TEST_F(OceanRender, SunGlitterStandsWhereTheSunReflects) {
    // Camera 20 m above open sea looking down at 25 deg towards the sun, which stands 25
    // deg high: the mirror point of the sun is the centre of the image. The glitter must
    // make it far brighter than the same row 20 deg of azimuth to either side, and the
    // brightest sea pixels must gather around it.
    const Session s = openSea(20.0, -25.0, 25.0);
    const ImageRGBAF hdr = renderHdr(s);
    ASSERT_TRUE(test::allFinite(hdr));
    const int cx = kSize.x / 2, cy = kSize.y / 2;
    auto meanLuminance = [&](int x0, int y0, int half) {
        double sum = 0.0;
        int n = 0;
        for (int y = y0 - half; y <= y0 + half; ++y)
            for (int x = x0 - half; x <= x0 + half; ++x, ++n) sum += luminance(at(hdr, x, y));
        return sum / n;
    };
    // 20 deg of azimuth at 60 deg vertical fov: 20 / 60 * 90 rows' worth of columns.
    const int offset = static_cast<int>(20.0 / 60.0 * kSize.y);
    const double centre = meanLuminance(cx, cy, 3);
    const double left = meanLuminance(cx - offset, cy, 3), right = meanLuminance(cx + offset, cy, 3);
    std::printf("glitter: centre %.4g, 20 deg left %.4g, right %.4g\n", centre, left, right);
    EXPECT_GT(centre, 4.0 * std::max(left, right));
    // Luminance-weighted centroid of the brightest 2 % of the sea (the rows below the
    // horizon, which stands 25 deg above the centre): in the sun's azimuth. Vertically the
    // glitter of a rough sea spreads from the horizon to near the camera (facets tilted by
    // a few sigma, sigma ~ 10 deg here), so only its column is asserted.
    std::vector<std::pair<float, glm::ivec2>> sea;
    for (int y = 0; y < cy + 20; ++y)
        for (int x = 0; x < kSize.x; ++x) sea.push_back({luminance(at(hdr, x, y)), {x, y}});
    std::sort(sea.begin(), sea.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    glm::dvec2 centroid(0.0);
    double weight = 0.0;
    for (std::size_t i = 0; i < sea.size() / 50; ++i) {
        centroid += glm::dvec2(sea[i].second) * double(sea[i].first);
        weight += sea[i].first;
    }
    centroid /= weight;
    std::printf("brightest sea pixels centred at (%.1f, %.1f), image centre (%d, %d)\n", centroid.x, centroid.y, cx, cy);
    EXPECT_NEAR(centroid.x, cx, 0.05 * kSize.x);
}

TEST_F(OceanRender, SunsetGlitterStandsBelowTheSun) {
    // The sun 4 deg above the horizon, the camera 20 m up looking 4 deg down at its mirror
    // image: the glitter column under the sun outshines the sea 20 deg to either side, and
    // the frame is finite although the sun's light grazes the sea.
    const Session s = openSea(20.0, -4.0, 4.0);
    const ImageRGBAF hdr = renderHdr(s);
    ASSERT_TRUE(test::allFinite(hdr));
    const int cx = kSize.x / 2, cy = kSize.y / 2;
    const int offset = static_cast<int>(20.0 / 60.0 * kSize.y);
    auto column = [&](int x0) {  // mean over 7 columns and the 10 rows below the centre
        double sum = 0.0;
        for (int y = cy - 10; y < cy; ++y)
            for (int x = x0 - 3; x <= x0 + 3; ++x) sum += luminance(at(hdr, x, y));
        return sum / 70.0;
    };
    const double centre = column(cx), left = column(cx - offset), right = column(cx + offset);
    std::printf("sunset glitter: centre %.4g, 20 deg left %.4g, right %.4g\n", centre, left, right);
    EXPECT_GT(centre, 4.0 * std::max(left, right));
}

TEST_F(OceanRender, GlitterFollowsWaveSlope) {
    // The same view under a light breeze and a strong wind: the rougher sea's slopes (the
    // waves' and the ripples' finer than the waves, Cox & Munk) spread the glitter over more
    // of the frame around the mirror point.
    Session calm = openSea(20.0, -25.0, 25.0);
    Session rough = calm;
    calm.scene.ocean.wind_speed_mps = 3.0;
    calm.scene.waves = ocean::generateWaves(calm.scene.ocean);
    rough.scene.ocean.wind_speed_mps = 15.0;
    rough.scene.waves = ocean::generateWaves(rough.scene.ocean);
    // Spread: the RMS horizontal distance from the sun's azimuth (the image's centre
    // column) of the glitter, i.e. of each sea pixel's excess over twice its row's median.
    auto spread = [&](const Session& s) {
        const ImageRGBAF hdr = renderHdr(s);
        double sum = 0.0, weight = 0.0;
        for (int y = 0; y < kSize.y / 2 + 20; ++y) {
            std::vector<float> row;
            for (int x = 0; x < kSize.x; ++x) row.push_back(luminance(at(hdr, x, y)));
            std::vector<float> sorted = row;
            std::nth_element(sorted.begin(), sorted.begin() + kSize.x / 2, sorted.end());
            const float median = sorted[kSize.x / 2];
            for (int x = 0; x < kSize.x; ++x) {
                const double excess = std::max(0.0f, row[x] - 2.0f * median);
                sum += excess * (x - kSize.x / 2) * (x - kSize.x / 2);
                weight += excess;
            }
        }
        return std::sqrt(sum / std::max(weight, 1e-30));
    };
    const double calmSpread = spread(calm), roughSpread = spread(rough);
    std::printf("glitter RMS width: calm %.2f px, rough %.2f px\n", calmSpread, roughSpread);
    EXPECT_GT(roughSpread, 1.5 * calmSpread);  // measured on llvmpipe: 4.9 and 9.1 px
}

TEST_F(OceanRender, SubmergedCameraGivesWaterNotNan) {
    // The same view from 3 m above and 3 m below the sea surface: below, the water body
    // takes the red out of everything (extinction 0.46 / m against 0.035 / m in blue) and
    // veils it in dim blue, so the frame is bluer and darker than above, and finite.
    Session s = openSea(5.0, 10.0, 50.0);
    const glm::dvec3 up = glm::normalize(s.camera.position);
    auto stats = [&](double altitude, double& redOverBlue, double& mean) {
        s.camera.position = up * (s.scene.planetRadiusM() + altitude);
        const ImageRGBAF hdr = renderHdr(s);
        EXPECT_TRUE(test::allFinite(hdr)) << altitude;
        double red = 0.0, blue = 0.0, sum = 0.0;
        for (int y = 0; y < kSize.y; ++y)
            for (int x = 0; x < kSize.x; ++x) {
                red += at(hdr, x, y)[0];
                blue += at(hdr, x, y)[2];
                sum += luminance(at(hdr, x, y));
            }
        redOverBlue = red / std::max(blue, 1e-30);
        mean = sum / (kSize.x * kSize.y);
    };
    double aboveRatio = 0.0, aboveMean = 0.0, belowRatio = 0.0, belowMean = 0.0;
    stats(3.0, aboveRatio, aboveMean);
    stats(-3.0, belowRatio, belowMean);
    ASSERT_GT(cameraDepthBelowSeaM(s.scene, s.camera), 0.0);
    std::printf("red / blue above %.3f below %.3f; mean luminance above %.4g below %.4g\n", aboveRatio, belowRatio,
                aboveMean, belowMean);
    EXPECT_LT(belowRatio, 0.5 * aboveRatio);
    EXPECT_LT(belowMean, 0.5 * aboveMean);
}

TEST_F(OceanRender, TenKilometresUnderTheSeaItIsDark) {
    // The sea raised 10 km over the beach: the camera, 2 m above the sand, is 10 km down. The
    // sand there was lit as if in air (a bright floor with a sharp horizon, as bright as from
    // 100 m up); the light reaching it has crossed 10 km of water (exp(-0.035 / m x 10 km) in
    // blue), so the frame is black but for rounding.
    Session s = session("beach");
    const auto meanLuminance = [&](const ImageRGBAF& hdr) {
        double sum = 0.0;
        for (std::size_t i = 0; i + 3 < hdr.pixels.size(); i += 4) sum += luminance(&hdr.pixels[i]);
        return sum / (hdr.pixels.size() / 4);
    };
    const double inAir = meanLuminance(renderHdr(s));
    s.scene.ocean.sea_level_m = 10000.0;
    ASSERT_GT(cameraDepthBelowSeaM(s.scene, s.camera), 9000.0);
    const ImageRGBAF deep = renderHdr(s);
    ASSERT_TRUE(test::allFinite(deep));
    std::printf("mean luminance in air %.4g, 10 km down %.4g\n", inAir, meanLuminance(deep));
    EXPECT_LT(meanLuminance(deep), 1e-6 * inAir);
    // 3 m down the sand is still lit, bluer than in air (red is gone after a few metres).
    s.scene.ocean.sea_level_m = 5.0;
    const ImageRGBAF shallow = renderHdr(s);
    EXPECT_GT(meanLuminance(shallow), 0.05 * inAir);
}

TEST_F(OceanRender, WaveEditsShowInTheNextFrame) {
    Session s = openSea(20.0, -25.0, 25.0);
    const ImageRGBAF before = renderHdr(s);
    s.scene.waves.front().amplitude_m *= 4.0;
    s.scene.waves.front().steepness *= 0.25;
    const ImageRGBAF after = renderHdr(s);
    int changed = 0;
    for (std::size_t i = 0; i < before.pixels.size(); ++i) changed += before.pixels[i] != after.pixels[i];
    EXPECT_GT(changed, 100);
    s.scene.time_s += 1.0;  // and the clock moves the waves
    const ImageRGBAF later = renderHdr(s);
    changed = 0;
    for (std::size_t i = 0; i < after.pixels.size(); ++i) changed += after.pixels[i] != later.pixels[i];
    EXPECT_GT(changed, 100);
}

TEST_F(OceanRender, FromSpaceTheCoastlineFollowsTheHeightField) {
    // 30 000 km out, both meshes sag a kilometre below the sphere between vertices, more
    // than a coastal plain is high: the sea must still cover exactly the pixels whose point
    // on the planet lies below sea level (the ocean pass wrote their depth), and leave the land.
    const Session s = session("space");
    const glm::ivec2 size{200, 200};
    renderer->render(s.scene, s.camera, size);
    // Water where the ocean pass wrote depth: the final depth differs from the copy taken before it.
    auto depthOf = [&](const gl::Texture& t) {
        std::vector<float> d(static_cast<std::size_t>(size.x) * size.y);
        glGetTextureImage(t.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(d.size() * sizeof(float)),
                          d.data());
        return d;
    };
    const std::vector<float> final = depthOf(renderer->targets().gbuffer().depth);
    const std::vector<float> seabed = depthOf(renderer->targets().seabedDepth());
    const glm::dmat4 viewFromClip = glm::inverse(s.camera.clipFromView(double(size.x) / size.y));
    int land = 0, sea = 0, wetLand = 0, drySea = 0;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const glm::dvec2 ndc((x + 0.5) / size.x * 2 - 1, (y + 0.5) / size.y * 2 - 1);
            const glm::dvec4 v = viewFromClip * glm::dvec4(ndc, 0.5, 1.0);
            const glm::dvec3 dir = s.camera.worldFromView() * glm::normalize(glm::dvec3(v) / v.w);
            const double t = test::nearestHitDouble(s.camera.position, dir, s.scene.planetRadiusM());
            if (t < 0.0) continue;
            const glm::dvec3 hit = s.camera.position + t * dir;
            const float height = s.ground.height(glm::vec3(glm::normalize(hit)));
            const std::size_t i = static_cast<std::size_t>(y) * size.x + x;  // GL rows, as read back
            const bool water = final[i] != seabed[i];
            if (height > 50.0f) {
                ++land;
                wetLand += water;
            } else if (height < -50.0f) {
                ++sea;
                drySea += !water;
            }
        }
    }
    std::printf("from space: %d land pixels, %d covered by sea; %d sea pixels, %d left dry\n", land, wetLand, sea, drySea);
    ASSERT_GT(land, 1000);
    ASSERT_GT(sea, 1000);
    EXPECT_LT(wetLand, land / 200);  // 0.5 %: pixels the hit-point test and the rasteriser see differently
    EXPECT_LT(drySea, sea / 200);
}

// Foam where the waves break (ocean_waves.glsl, oceanFoam): the beach and the open sea
// rendered with the foam and with it compiled out. Sea pixels over water deeper than the
// breaking depth of the whole sea state (the sum of the amplitudes / 0.39) are the same to the
// bit (the loop never runs there); sea pixels over water shallower than the largest wave's
// breaking depth are brighter on the whole, by at least half the cover the CPU twin
// (ocean/waves.h, foamCover) gives their depths (a white of 0.6 over a sea of a few per cent).
// Able to fail: without the foam nothing changes; foam in the open sea breaks the first check.
TEST_F(OceanRender, FoamBrightensTheSurfAndNothingElse) {
    Renderer off(test::shadersWith("planet_test_foam_off", "ocean/sea_light.frag", "#define OCEAN_FOAM 1",
                                   "#define OCEAN_FOAM 0"),
                 atmosphere::TableSizes::reduced());
    int deep = 0, deepChanged = 0, surf = 0;
    double lumWith = 0.0, lumWithout = 0.0, cover = 0.0;
    for (const std::string view : {"beach", "sea"}) {
        Session s = session(view);
        s.scene.clouds.enabled = false;
        renderer->render(s.scene, s.camera, kSize);
        const ImageRGBAF with = readTextureRGBAF(renderer->targets().surfaceRadiance(), kSize.x, kSize.y);
        const ImageRGBAF distance = readTextureRGBAF(renderer->targets().surfaceDistance(), kSize.x, kSize.y);
        off.render(s.scene, s.camera, kSize);
        const ImageRGBAF without = readTextureRGBAF(off.targets().surfaceRadiance(), kSize.x, kSize.y);
        double amplitudes = 0.0, largest = 0.0;
        for (const ocean::GerstnerWave& w : s.scene.waves) {
            amplitudes += w.amplitude_m;
            largest = std::max(largest, w.amplitude_m);
        }
        for (int row = 0; row < kSize.y; ++row) {
            for (int x = 0; x < kSize.x; ++x) {
                const double d = test::pixelAt(distance, x, row)[0];
                if (!(d > 0.0)) continue;
                const glm::dvec3 dir = test::pixelRay(s.camera, kSize, x, row);
                const glm::dvec3 up = glm::normalize(s.camera.position + dir * d);
                const double depth = s.scene.ocean.sea_level_m - s.ground.height(glm::vec3(up));
                const float* a = test::pixelAt(with, x, row);
                const float* b = test::pixelAt(without, x, row);
                if (depth > amplitudes / 0.39 + 0.5) {
                    ++deep;
                    if (a[0] != b[0] || a[1] != b[1] || a[2] != b[2]) ++deepChanged;
                } else if (depth > 0.05 && depth < largest / 0.39) {
                    ++surf;
                    lumWith += luminance(a);
                    lumWithout += luminance(b);
                    cover += ocean::foamCover(s.scene.waves, depth);
                }
            }
        }
    }
    std::printf("foam: %d deep sea pixels (%d changed), %d surf pixels: mean luminance %.5f -> %.5f, mean CPU cover "
                "%.3f\n",
                deep, deepChanged, surf, lumWithout / std::max(surf, 1), lumWith / std::max(surf, 1),
                cover / std::max(surf, 1));
    EXPECT_GT(deep, 1000);
    EXPECT_EQ(deepChanged, 0);
    ASSERT_GT(surf, 50);
    EXPECT_GT(cover / surf, 0.02);
    EXPECT_GT(lumWith, lumWithout * (1.0 + 0.5 * cover / surf));
}
