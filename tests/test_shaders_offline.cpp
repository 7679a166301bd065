// Offline validation: every shader stage under shaders/, expanded by our
// #include mechanism exactly as the driver sees it, passes glslangValidator.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "atmosphere/uniforms.h"
#include "gl/shader_source.h"
#include "process.h"
#include "render/renderer.h"

namespace fs = std::filesystem;

TEST(ShadersOffline, EveryStageValidatesWithGlslang) {
    const fs::path root = fs::path(PLANET_SOURCE_DIR) / "shaders";
    const fs::path tmp = fs::path(::testing::TempDir()) / ("glslang_" + std::to_string(::getpid()));
    fs::create_directories(tmp);
    int validated = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const std::string file = fs::relative(entry.path(), root).generic_string();
        const std::string stage = planet::gl::shaderStageName(file);
        if (stage.empty()) continue;
        // Stages made of atmosphere files (the precompute shaders, passes that
        // include the model) need the table sizes and texture types their
        // program builders inject: atmosphereShaderDefines(), as GpuPrecompute does.
        auto expanded = planet::gl::expandShader(root, file, planet::gl::shaderPreamble());
        const bool atmosphere = std::any_of(expanded.files.begin(), expanded.files.end(),
                                            [](const std::string& f) { return f.starts_with("atmosphere/"); });
        if (atmosphere)
            expanded = planet::gl::expandShader(
                root, file,
                planet::gl::shaderPreamble() + planet::atmosphere::atmosphereShaderDefines(planet::atmosphere::TableSizes{}));
        // Programs compiled in variants (src/render/atmosphere_program.h: ELEK_TABLE 0 and 1, and
        // for the sky passes LIGHT_SHAFTS_TERRAIN 0 and 1) are checked in each.
        std::vector<std::string> variants{""};
        if (expanded.text.find("ELEK_TABLE") != std::string::npos)
            variants = {"#define ELEK_TABLE 0\n", "#define ELEK_TABLE 1\n"};
        if (file.starts_with("render/sky")) {
            std::vector<std::string> withShafts;
            for (const std::string& v : variants)
                for (const char* shafts : {"#define LIGHT_SHAFTS_TERRAIN 0\n", "#define LIGHT_SHAFTS_TERRAIN 1\n"})
                    withShafts.push_back(v + shafts);
            variants = withShafts;
        }
        // The programs' other builds, each where its source tests its define (the marker): every
        // variant so far once more with each build's defines.
        struct Build {
            const char* marker;
            std::vector<const char*> builds;  // each a build of its own: its defines added to every variant so far
            bool beforeStill = false;         // added to the variants before the still builds instead (it defines STILL_FRAME)
        };
        const Build builds[] = {
            // The reconstruction's still-frame programs (src/render/renderer.cpp: STILL_FRAME, STILL_FRAME_UNJITTERED).
            {"#ifdef STILL_FRAME", {"#define STILL_FRAME\n"}},
            {"#ifdef STILL_FRAME_UNJITTERED", {"#define STILL_FRAME_UNJITTERED 1\n"}, true},
            // The programs for a camera under the sea (sky and ocean: UNDER_WATER 1).
            {"#ifndef UNDER_WATER", {"#define UNDER_WATER 1\n"}},
            // The ocean's flat-mirror and smooth-mirror programs (src/ocean/ocean_pass.cpp).
            {"#if OCEAN_FLAT_MIRROR", {"#define OCEAN_FLAT_MIRROR 1\n"}},
            {"#if OCEAN_SMOOTH_MIRROR", {"#define OCEAN_SMOOTH_MIRROR 1\n"}},
            // The sea's light on the open sea (src/ocean/ocean_pass.cpp: OPEN_SEA 1).
            {"#ifndef OPEN_SEA", {"#define OPEN_SEA 1\n"}},
            // The ocean mesh's fragments in their far-field build (OCEAN_FAR_FIELD 1).
            {"#if !OCEAN_FAR_FIELD", {"#define OCEAN_FAR_FIELD 1\n"}},
            // The surface light's program for the sea floor's dark depths (SEA_FLOOR_DARK 1).
            {"#if !SEA_FLOOR_DARK", {"#define SEA_FLOOR_DARK 1\n"}},
            // The sea reflection's spread and its every-pixel list (the modes of Renderer::seaReflection_).
            {"#if SEA_REFLECTION_COMPOSE", {"#define SEA_REFLECTION_COMPOSE 1\n", "#define SEA_REFLECTION_LIST_ALL 1\n"}},
            // Every program that reads the clouds, in its far-field build (src/render/atmosphere_program.h:
            // CLOUD_FAR_FIELD_ONLY 1, from high up) and in its build for a frame without clouds (CLOUDS_OFF 1,
            // never with the far field's).
            {"#if CLOUD_FAR_FIELD_ONLY", {"#define CLOUD_FAR_FIELD_ONLY 1\n", "#define CLOUDS_OFF 1\n"}},
            // The sky passes' builds for what their pixels see (src/render/atmosphere_program.h), together.
            {"#if NO_SUN_DISC", {"#define NO_SUN_DISC 1\n#define CAMERA_IN_AIR 1\n"}},
            // The surface light's marks in one pass, where the GL has ARB_shader_stencil_export.
            {"#if STENCIL_EXPORT", {"#define STENCIL_EXPORT 1\n"}},
            // The reduced-rate lattice's marks of the rays that meet no cloud (src/render/renderer.cpp).
            {"#ifdef SPARSE_LATTICE", {"#define SPARSE_LATTICE 1\n"}},
        };
        const std::vector<std::string> beforeStill = variants;  // STILL_FRAME_UNJITTERED: one of the still builds
        for (const Build& b : builds) {
            if (expanded.text.find(b.marker) == std::string::npos) continue;
            const std::vector<std::string>& base = b.beforeStill ? beforeStill : variants;
            std::vector<std::string> more;
            for (const char* defines : b.builds)
                for (const std::string& v : base) more.push_back(v + defines);
            variants.insert(variants.end(), more.begin(), more.end());
        }
        for (const std::string& variant : variants) {
            std::string text = expanded.text;
            text.insert(text.find('\n') + 1, variant);  // after #version
            const fs::path out = tmp / ("shader." + stage);
            std::ofstream(out) << text;
            const auto r = planet::test::runCommand(std::string(GLSLANG_VALIDATOR) + " " + out.string());
            EXPECT_EQ(r.exitCode, 0) << file << " " << variant << ":\n"
                                     << planet::gl::translateShaderLog(r.output, expanded.files);
            ++validated;
        }
    }
    fs::remove_all(tmp);
    EXPECT_GE(validated, 4);  // fullscreen.vert, placeholder_sphere.frag, lighting.frag, tonemap.frag
}

TEST(ShadersOffline, ValidatorRejectsABrokenShader) {
    // Guards the test above against a validator that accepts anything.
    const fs::path out = fs::path(::testing::TempDir()) / ("broken_" + std::to_string(::getpid()) + ".frag");
    std::ofstream(out) << "#version 450 core\nvoid main() { undefinedThing = 1.0; }\n";
    const auto r = planet::test::runCommand(std::string(GLSLANG_VALIDATOR) + " " + out.string());
    fs::remove(out);
    EXPECT_NE(r.exitCode, 0);
}
