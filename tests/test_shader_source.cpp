// Shader #include expansion and compile-log translation (CPU only).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gl/shader_source.h"

namespace fs = std::filesystem;
using planet::gl::expandShader;
using planet::gl::ShaderError;
using planet::gl::translateShaderLog;

namespace {

class ShaderSourceTest : public ::testing::Test {
protected:
    void SetUp() override {
        root = fs::path(::testing::TempDir()) / ("shader_source_" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root / "common");
    }
    void TearDown() override { fs::remove_all(root); }
    void write(const std::string& file, const std::string& text) { std::ofstream(root / file) << text; }
    fs::path root;
};

}  // namespace

TEST_F(ShaderSourceTest, ExpandsNestedIncludesWithLineDirectives) {
    write("main.frag", "// main\n#include \"common/a.glsl\"\nvoid main() {}\n");
    write("common/a.glsl", "#include \"common/b.glsl\"\nfloat a() { return b(); }\n");
    write("common/b.glsl", "float b() { return 1.0; }\n");
    const auto e = expandShader(root, "main.frag", "#version 450 core\n");
    ASSERT_EQ(e.files, (std::vector<std::string>{"main.frag", "common/a.glsl", "common/b.glsl"}));
    const std::string expected =
        "#version 450 core\n#line 1 0\n// main\n#line 1 1\n#line 1 2\nfloat b() { return 1.0; }\n#line 2 1\n"
        "float a() { return b(); }\n#line 3 0\nvoid main() {}\n";
    EXPECT_EQ(e.text, expected);
}

TEST_F(ShaderSourceTest, IncludesEachFileOnce) {
    write("main.frag", "#include \"common/b.glsl\"\n#include \"common/b.glsl\"\nvoid main() {}\n");
    write("common/b.glsl", "float b() { return 1.0; }\n");
    const auto e = expandShader(root, "main.frag", "#version 450 core\n");
    const auto first = e.text.find("float b()");
    ASSERT_NE(first, std::string::npos);
    EXPECT_EQ(e.text.find("float b()", first + 1), std::string::npos);
}

TEST_F(ShaderSourceTest, MissingIncludeNamesTheIncludingFileAndLine) {
    write("main.frag", "void f();\n\n#include \"common/nope.glsl\"\n");
    try {
        expandShader(root, "main.frag", "#version 450 core\n");
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("main.frag:3"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("common/nope.glsl"), std::string::npos) << e.what();
    }
}

TEST_F(ShaderSourceTest, IncludeCycleIsAnError) {
    write("common/a.glsl", "#include \"common/b.glsl\"\n");
    write("common/b.glsl", "#include \"common/a.glsl\"\n");
    write("main.frag", "#include \"common/a.glsl\"\n");
    EXPECT_THROW(expandShader(root, "main.frag", "#version 450 core\n"), ShaderError);
}

TEST(ShaderLog, TranslatesMesaNvidiaAndGlslangLocations) {
    const std::vector<std::string> files{"render/x.frag", "common/math.glsl"};
    EXPECT_EQ(translateShaderLog("1:12(3): error: `foo' undeclared", files),
              "common/math.glsl:12:3: error: `foo' undeclared");
    EXPECT_EQ(translateShaderLog("0(7) : error C1008: undefined variable", files),
              "render/x.frag:7 : error C1008: undefined variable");
    EXPECT_EQ(translateShaderLog("ERROR: 1:4: 'x' : undeclared identifier", files),
              "ERROR: common/math.glsl:4: 'x' : undeclared identifier");
    EXPECT_EQ(translateShaderLog("plain text", files), "plain text");
}

TEST(ShaderLog, StageNamesFromExtensions) {
    EXPECT_EQ(planet::gl::shaderStageName("terrain/terrain.tese"), "tese");
    EXPECT_EQ(planet::gl::shaderStageName("render/lighting.frag"), "frag");
    EXPECT_EQ(planet::gl::shaderStageName("common/math.glsl"), "");
}
