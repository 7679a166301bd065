// Issue 15: from high up (the sea's far field, src/ocean/far_field.h) the sea pixels with no land within
// reach of their reflected ray or their sun ray are marked apart in the stencil (ocean/ocean.frag's
// openSea, OceanPass::kOpenSeaStencil) and lit by the water's light built without the terrain
// reflection's and shadow's code (ocean/sea_light.frag, OPEN_SEA), since a software renderer ran that
// code at every sea pixel, masked. The mark must be a bound: every pixel it marks open, the light's own
// tests find open too. So the frame is the one the whole program gives everywhere, value for value: the
// surface radiance, the sky the sea reflects where the terrain may be, the pixels listed for the terrain
// reflection's search, the final image. Under the noon sun, a low sun (the terrain's shadows near the
// coasts), from space, and with a long swell that the pixels resolve (the reflected rays lean with the
// waves: the mark's rise bound, which marks fewer pixels open there). Able to fail: a mark that leaves
// out the reflected ray's reach, or marks every sea pixel open, gives another frame (checked on copies
// of the shaders). What this cannot show: a mark that left out the sun ray's reach gives the same frames
// here (tried: from orbit no terrain shadow falls on the sea in these views, and the shadow's march
// finds what the open sea's program takes, lit); under the low sun the sun's reach keeps 52 more
// pixels from the mark than at noon.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/session.h"
#include "gl_test_support.h"
#include "render/readback.h"
#include "render/renderer.h"

using namespace planet;

namespace {

constexpr glm::ivec2 kSize{160, 90};

class OpenSea : public test::GLTest {};

struct Frame {
    ImageRGBAF surface, skyReflection, hdr;
    std::vector<glm::ivec2> listed;  // for the terrain reflection's search, sorted
    long long open = 0, sea = 0;     // pixels marked kOpenSeaStencil, and kSeaStencil
    bool farField = false, marksOpenSea = false;
};

Frame render(Renderer& r, const Session& s, bool split) {
    r.setOpenSeaSplit(split);
    r.render(s.scene, s.camera, kSize);
    Frame f;
    f.surface = readTextureRGBAF(r.targets().surfaceRadiance(), kSize.x, kSize.y);
    f.skyReflection = readTextureRGBAF(r.targets().seaSkyReflection(), kSize.x, kSize.y);
    f.hdr = readTextureRGBAF(r.targets().hdr(), kSize.x, kSize.y);
    f.listed = r.targets().readTerrainReflectionList();
    std::sort(f.listed.begin(), f.listed.end(),
              [](glm::ivec2 a, glm::ivec2 b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
    for (const GLubyte v : test::readStencil(r.targets().gbuffer().depth, kSize)) {
        f.open += v == OceanPass::kOpenSeaStencil;
        f.sea += v == OceanPass::kSeaStencil;
    }
    f.farField = r.ocean().farField();
    f.marksOpenSea = r.ocean().marksOpenSea();
    return f;
}

std::size_t differing(const ImageRGBAF& a, const ImageRGBAF& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i] ? 1 : 0;
    return n;
}

// Values of the two frames that differ, in all the targets and the list (its length and its pixels).
std::size_t differences(const Frame& a, const Frame& b) {
    return differing(a.surface, b.surface) + differing(a.skyReflection, b.skyReflection) + differing(a.hdr, b.hdr) +
           (a.listed == b.listed ? 0 : 1 + std::max(a.listed.size(), b.listed.size()));
}

struct Case {
    const char* name;
    Session session;
};

// The sun `zenithDeg` from the camera's vertical, towards the east (the views look east).
void sunTowardsEast(Session& s, double zenithDeg) {
    const glm::dvec3 up = glm::normalize(s.camera.position);
    const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), up));
    const double zenith = glm::radians(zenithDeg);
    const glm::dvec3 sun = std::cos(zenith) * up + std::sin(zenith) * east;
    s.scene.sun.latitude_deg = glm::degrees(std::asin(sun.z));
    s.scene.sun.longitude_deg = glm::degrees(std::atan2(sun.y, sun.x));
}

std::vector<Case> cases() {
    std::vector<Case> c;
    const auto load = [](const char* view) {
        Session s = loadSession(test::repoPaths(), "earth", view);
        s.scene.render.temporal = false;
        return s;
    };
    c.push_back({"orbit", load("orbit")});
    Session low = load("orbit");
    sunTowardsEast(low, 80.0);
    c.push_back({"orbit, low sun", low});
    c.push_back({"space", load("space")});
    // A swell 40 km long and 4 km high (no sea's, a test's), which the orbit's pixels (5 to 15 km on the
    // sea at this size) resolve: its slopes (A k 0.63) lean the water's normal, and the reflected rays
    // with it, by tens of degrees.
    Session swell = load("orbit");
    ocean::GerstnerWave wave;
    wave.origin = glm::normalize(glm::dvec3(0.3, -0.8, 0.5));
    wave.amplitude_m = 4000.0;
    wave.wavelength_m = 40000.0;
    wave.steepness = 1.0;
    wave.speed_mps = ocean::deepWaterSpeed(wave.wavelength_m);
    swell.scene.waves.insert(swell.scene.waves.begin(), wave);
    c.push_back({"orbit, swell", swell});
    return c;
}

}  // namespace

TEST_F(OpenSea, TheOpenSeasProgramLightsTheMarkedSeaAsTheWholeProgramDoes) {
    auto renderer = std::make_unique<Renderer>(test::repoPaths().shaders(), atmosphere::TableSizes::reduced());
    if (!epoxy_has_gl_extension("GL_ARB_shader_stencil_export")) GTEST_SKIP() << "no ARB_shader_stencil_export";
    long long openAtOrbit = 0;
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Frame whole = render(*renderer, c.session, false);
        const Frame split = render(*renderer, c.session, true);
        const std::string name = c.name;
        if (name == "orbit") openAtOrbit = split.open;
        // The swell's lean lowers the reflected rays' least rise, and fewer pixels are sure to be open
        // (a mark that left the lean out marked as many as without the swell).
        if (name == "orbit, swell") {
            EXPECT_LT(split.open, openAtOrbit * 4 / 5);
        }
        std::printf("%-15s %lld sea pixels marked open, %lld not; %zu listed for the terrain reflection; %zu values "
                    "differ\n", c.name, split.open, split.sea, split.listed.size(), differences(whole, split));
        ASSERT_TRUE(split.farField && split.marksOpenSea);
        EXPECT_EQ(differences(whole, split), 0u);
        EXPECT_GT(split.open, (split.open + split.sea) / 2) << "most of the sea seen from high up is open";
        EXPECT_GT(split.sea, 0) << "the coasts";
    }
    renderer->setOpenSeaSplit(true);
}

TEST_F(OpenSea, AMarkThatIsNoBoundGivesAnotherFrame) {
    if (!epoxy_has_gl_extension("GL_ARB_shader_stencil_export")) GTEST_SKIP() << "no ARB_shader_stencil_export";
    struct Mutation {
        const char* what;
        const char* from;
        const char* to;
        const char* view;  // the case where it shows
    };
    const Mutation mutations[] = {
        {"the reflected ray's reach left out", "!terrainMayBeReflected(reachKm.x", "!terrainMayBeReflected(0.0 * reachKm.x",
         "orbit"},
        {"every sea pixel open", "? OPEN_SEA_STENCIL : SEA_STENCIL", "? OPEN_SEA_STENCIL : OPEN_SEA_STENCIL",
         "orbit, low sun"},
    };
    const std::vector<Case> all = cases();
    for (const Mutation& m : mutations) {
        SCOPED_TRACE(m.what);
        const auto it = std::find_if(all.begin(), all.end(), [&](const Case& c) { return std::string(c.name) == m.view; });
        ASSERT_NE(it, all.end());
        Renderer mutated(test::shadersWith("planet_test_open_sea_mutated", "ocean/ocean.frag", m.from, m.to),
                         atmosphere::TableSizes::reduced());
        const Frame whole = render(mutated, it->session, false);
        const Frame split = render(mutated, it->session, true);
        std::printf("%-26s (%s): %zu values differ\n", m.what, m.view, differences(whole, split));
        EXPECT_GT(differences(whole, split), 0u);
    }
}
