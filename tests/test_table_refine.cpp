// The explorer's start without a wait (issue 14): an Atmosphere planned with a starter makes
// the starter's tables in its first update() and refines them to the target sizes in the
// background, one chunk per update(), with the same chunked rebuild as a parameter edit; the
// tables it ends with are those made at the target sizes from the start, and so is the frame
// a Renderer draws after the swap (the programs that read the tables rebuilt with the new
// sizes). The refined tables are cached, so the next plan needs no starter.
//
// Small sizes keep it quick on two cores: the target is the reduced tables, the starter a
// explorer's (smaller, and fewer scattering orders where the scene asks for more).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "atmosphere/atmosphere.h"
#include "atmosphere/elek_table.h"
#include "atmosphere/parameters.h"
#include "atmosphere/precompute_gpu.h"
#include "atmosphere/table_cache.h"
#include "gl_test_support.h"
#include "render/readback.h"
#include "render/renderer.h"

namespace fs = std::filesystem;
using namespace planet;
using namespace planet::atmosphere;

namespace {

// The explorer's starter (half the reduced sizes, 2 orders), and one with a single order.
const StarterTables kStarter = defaultStarterTables();
const TableSizes kStarterSizes = kStarter.sizes;
const StarterTables kSingleOrderStarter{kStarterSizes, 1};
const TableSizes kTarget = TableSizes::reduced();
constexpr int kTargetOrders = 2;
constexpr int kMaxUpdates = 2000;  // a bound on the loops, not a time limit

fs::path freshRoot(const std::string& name) {
    const fs::path root = fs::path(PLANET_TEST_OUT) / "table_refine" / name;
    fs::remove_all(root);
    return root;
}

Session earthSession() {
    Session s = loadSession(test::repoPaths(), "earth", "orbit");
    s.scene.atmosphere.scattering_orders = kTargetOrders;
    s.scene.clouds.enabled = false;  // the atmosphere alone: quicker frames
    s.scene.time_s = 0.0;
    return s;
}

// The largest difference between two tables relative to the larger texel value of each
// channel's table (0 when bit for bit equal).
double worstRelativeDifference(const std::vector<glm::dvec4>& a, const std::vector<glm::dvec4>& b) {
    if (a.size() != b.size()) return INFINITY;
    double scale = 0.0, worst = 0.0;
    for (const glm::dvec4& v : b)
        for (int c = 0; c < 4; ++c) scale = std::max(scale, std::abs(v[c]));
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 4; ++c) worst = std::max(worst, std::abs(a[i][c] - b[i][c]));
    return scale > 0.0 ? worst / scale : worst;
}

// The tables made directly at the target sizes, as a renderer planned without a starter makes them.
GpuTables directTables(const Scene& scene) {
    GpuPrecompute precompute(test::repoPaths().shaders(), kTarget);
    return precompute.compute(makeAtmosphereParameters(scene), scene.atmosphere.scattering_orders, {},
                              /*elekTable=*/true);
}

void expectSameTables(const GpuTables& got, const GpuTables& want) {
    const AtmosphereTables a = readBack(got), b = readBack(want);
    ASSERT_EQ(a.sizes, b.sizes);
    EXPECT_LE(worstRelativeDifference(a.transmittance.texels, b.transmittance.texels), 1e-6);
    EXPECT_LE(worstRelativeDifference(a.scattering.texels, b.scattering.texels), 1e-6);
    EXPECT_LE(worstRelativeDifference(a.singleMie.texels, b.singleMie.texels), 1e-6);
    EXPECT_LE(worstRelativeDifference(a.irradiance.texels, b.irradiance.texels), 1e-6);
    const ElekTables ea = readBackElek(got), eb = readBackElek(want);
    EXPECT_LE(worstRelativeDifference(ea.scattering.texels, eb.scattering.texels), 1e-6);
    EXPECT_LE(worstRelativeDifference(ea.singleMie.texels, eb.singleMie.texels), 1e-6);
}

// update() until the tables are the target's; returns the calls it took.
int refine(Atmosphere& atmosphere, const Scene& scene) {
    int updates = 0;
    while ((atmosphere.refining() || atmosphere.rebuilding()) && updates < kMaxUpdates) {
        atmosphere.update(scene);
        ++updates;
    }
    return updates;
}

class TableRefineTest : public test::GLTest {};

}  // namespace

TEST_F(TableRefineTest, StartsWithTheStarterAndRefinesToTheTargetTables) {
    const fs::path root = freshRoot("refine");
    const Session s = earthSession();
    {
        Atmosphere atmosphere(test::repoPaths().shaders(), TablePlan(kTarget, kStarter, root));
        EXPECT_EQ(atmosphere.sizes(), kStarterSizes);  // what the programs are first built for
        atmosphere.update(s.scene);
        ASSERT_TRUE(atmosphere.ready());  // tables after the first update
        EXPECT_EQ(atmosphere.sizes(), kStarterSizes);
        EXPECT_EQ(atmosphere.tables().sizes, kStarterSizes);
        EXPECT_TRUE(atmosphere.refining());

        atmosphere.update(s.scene);  // the refinement starts, a chunk at a time
        EXPECT_TRUE(atmosphere.rebuilding());
        EXPECT_EQ(atmosphere.sizes(), kStarterSizes);  // the starter stays in use meanwhile
        const int updates = refine(atmosphere, s.scene);
        std::printf("refined in %d more updates\n", updates);
        EXPECT_GT(updates, 2);  // spread over frames
        ASSERT_FALSE(atmosphere.refining());
        ASSERT_FALSE(atmosphere.rebuilding());
        EXPECT_EQ(atmosphere.sizes(), kTarget);
        expectSameTables(atmosphere.tables(), directTables(s.scene));
        atmosphere.update(s.scene);  // nothing more to do
        EXPECT_FALSE(atmosphere.rebuilding());
    }  // the destructor waits for the cache's writer

    // The refined tables are in the cache: the next start needs no starter.
    const std::string key = tableCacheKey(makeAtmosphereParameters(s.scene), kTarget, kTargetOrders,
                                          atmosphereModelSource(test::repoPaths().shaders()));
    std::string reason;
    EXPECT_TRUE(loadTables(root / key, key, kTarget, &reason).has_value()) << reason;
    const TablePlan next = startPlan(s.scene, kTarget, kStarter, test::repoPaths().shaders(), root);
    EXPECT_FALSE(next.starter.has_value());
    Atmosphere warm(test::repoPaths().shaders(), next);
    warm.update(s.scene);
    EXPECT_EQ(warm.sizes(), kTarget);
    EXPECT_FALSE(warm.refining());
    warm.update(s.scene);
    EXPECT_FALSE(warm.rebuilding());
}

TEST_F(TableRefineTest, PlanStartsFromTheCheapestCachedEntryOrTheStarter) {
    const fs::path root = freshRoot("plan");
    const Session s = earthSession();
    const fs::path shaders = test::repoPaths().shaders();
    // Nothing cached: the starter, at most the scene's orders.
    TablePlan plan = startPlan(s.scene, kTarget, {kStarterSizes, 5}, shaders, root);
    ASSERT_TRUE(plan.starter.has_value());
    EXPECT_EQ(plan.starter->sizes, kStarterSizes);
    EXPECT_EQ(plan.starter->orders, kTargetOrders);
    EXPECT_EQ(plan.firstSizes(), kStarterSizes);
    // A starter that is the target: nothing to refine.
    EXPECT_FALSE(startPlan(s.scene, kTarget, {kTarget, kTargetOrders}, shaders, root).starter.has_value());
    // The reduced tables cached (a run with --tables reduced): the starter of a larger target.
    {
        Atmosphere reduced(shaders, TablePlan(kTarget, std::nullopt, root));
        reduced.update(s.scene);
    }
    plan = startPlan(s.scene, TableSizes{}, kStarter, shaders, root);
    ASSERT_TRUE(plan.starter.has_value());
    EXPECT_EQ(plan.starter->sizes, kTarget);
    EXPECT_EQ(plan.starter->orders, kTargetOrders);
}

TEST_F(TableRefineTest, AnEditWhileRefiningRetargetsTheRefinement) {
    const fs::path root = freshRoot("edit");
    Session s = earthSession();
    Atmosphere atmosphere(test::repoPaths().shaders(), TablePlan(kTarget, kSingleOrderStarter, root));
    atmosphere.update(s.scene);
    for (int i = 0; i < 5; ++i) atmosphere.update(s.scene);
    ASSERT_TRUE(atmosphere.rebuilding());
    ASSERT_TRUE(atmosphere.refining());
    s.scene.atmosphere.rayleigh_scattering_per_m *= 1.5;
    s.scene.atmosphere.ground_albedo = glm::dvec3(0.3);
    atmosphere.update(s.scene);  // the refinement starts over with the new air
    EXPECT_TRUE(atmosphere.refining());
    EXPECT_EQ(atmosphere.sizes(), kStarterSizes);
    refine(atmosphere, s.scene);
    ASSERT_FALSE(atmosphere.refining());
    ASSERT_FALSE(atmosphere.rebuilding());
    EXPECT_EQ(atmosphere.sizes(), kTarget);
    expectSameTables(atmosphere.tables(), directTables(s.scene));
}

TEST_F(TableRefineTest, FrameAfterTheSwapEqualsAFrameWithTargetTablesFromTheStart) {
    const fs::path root = freshRoot("frame");
    const Session s = earthSession();
    const glm::ivec2 size{48, 27};
    Renderer refined(test::repoPaths().shaders(), TablePlan(kTarget, kStarter, root), s.continents);
    refined.render(s.scene, s.camera, size);
    EXPECT_EQ(refined.atmosphere().sizes(), kStarterSizes);
    EXPECT_TRUE(test::allFinite(readTextureRGBAF(refined.targets().hdr(), size.x, size.y)));
    bool programsRebuilt = false;
    for (int frame = 0; refined.atmosphere().refining() && frame < kMaxUpdates; ++frame) {
        refined.render(s.scene, s.camera, size);
        programsRebuilt = programsRebuilt || refined.lastPrepare().atmosphereProgramsRebuilt;
    }
    ASSERT_FALSE(refined.atmosphere().refining());
    EXPECT_TRUE(programsRebuilt);
    EXPECT_TRUE(refined.shaderErrors().empty());

    // Its own cache: tables computed at the target sizes, not the refined ones read back.
    Renderer direct(test::repoPaths().shaders(), TablePlan(kTarget, std::nullopt, freshRoot("frame-direct")),
                    s.continents);
    while (direct.frameIndex() < refined.frameIndex()) direct.render(s.scene, s.camera, size);  // the same frame index
    for (Renderer* r : {&refined, &direct}) {
        r->dropHistory();
        r->render(s.scene, s.camera, size);
    }
    const ImageRGBAF a = readTextureRGBAF(refined.targets().hdr(), size.x, size.y);
    const ImageRGBAF b = readTextureRGBAF(direct.targets().hdr(), size.x, size.y);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
    EXPECT_EQ(differing, 0u);
}
