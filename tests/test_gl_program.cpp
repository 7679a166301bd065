// Shader programs under a real (headless) GL context: compile errors name the
// real file and line, and hot reload keeps the last good program.
#include <filesystem>
#include <fstream>
#include <thread>

#include "gl/live_objects.h"
#include "gl/program.h"
#include "gl_test_support.h"

namespace fs = std::filesystem;
using namespace planet;

namespace {

class ProgramTest : public test::GLTest {
protected:
    void SetUp() override {
        GLTest::SetUp();
        root = fs::path(::testing::TempDir()) / ("program_test_" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root / "common");
        write("common/colour.glsl", "vec3 colour() {\n    return vec3(1.0, 0.5, 0.25);\n}\n");
        write("fill.frag", "#include \"common/colour.glsl\"\nout vec4 c;\nvoid main() { c = vec4(colour(), 1.0); }\n");
        write("fill.vert", "void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n");
    }
    void TearDown() override {
        fs::remove_all(root);
        GLTest::TearDown();
    }
    void write(const std::string& file, const std::string& text) {
        std::ofstream(root / file) << text;
        // Make each edit visible to the mtime poll even within one clock tick.
        static auto stamp = fs::file_time_type::clock::now();
        stamp += std::chrono::seconds(1);
        fs::last_write_time(root / file, stamp);
    }
    gl::ShaderSources sources() const { return {root, "#version 450 core\n"}; }
    fs::path root;
};

}  // namespace

TEST_F(ProgramTest, BuildsProgramFromFilesWithIncludes) {
    const gl::Program p = gl::buildProgram(sources(), {"fill", {"fill.vert", "fill.frag"}});
    EXPECT_NE(p.id(), 0u);
    EXPECT_NE(std::find(p.files.begin(), p.files.end(), "common/colour.glsl"), p.files.end());
}

TEST_F(ProgramTest, CompileErrorNamesIncludedFileAndLine) {
    write("common/colour.glsl", "vec3 colour() {\n    float x = 1.0;\n    return undefinedThing;\n}\n");
    try {
        gl::buildProgram(sources(), {"fill", {"fill.vert", "fill.frag"}});
        FAIL() << "expected a ShaderError";
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("common/colour.glsl:3"), std::string::npos) << e.what();
    }
}

TEST_F(ProgramTest, CompileErrorAfterIncludeNamesMainFileLine) {
    write("fill.frag", "#include \"common/colour.glsl\"\nout vec4 c;\nvoid main() { c = nope; }\n");
    try {
        gl::buildProgram(sources(), {"fill", {"fill.vert", "fill.frag"}});
        FAIL() << "expected a ShaderError";
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("fill.frag:3"), std::string::npos) << e.what();
    }
}

TEST_F(ProgramTest, HotReloadKeepsLastGoodProgramAndReportsError) {
    gl::HotProgram hot(sources(), {"fill", {"fill.vert", "fill.frag"}});
    const GLuint good = hot.id();
    EXPECT_FALSE(hot.reloadIfChanged());  // nothing changed

    write("common/colour.glsl", "vec3 colour() { return broken; }\n");
    EXPECT_FALSE(hot.reloadIfChanged());
    EXPECT_EQ(hot.id(), good);
    EXPECT_NE(hot.error().find("common/colour.glsl:1"), std::string::npos) << "error: " << hot.error();
    EXPECT_TRUE(glIsProgram(hot.id()));

    write("common/colour.glsl", "vec3 colour() { return vec3(0.0); }\n");
    EXPECT_TRUE(hot.reloadIfChanged());
    EXPECT_TRUE(hot.error().empty());
    EXPECT_TRUE(glIsProgram(hot.id()));
}

TEST_F(ProgramTest, ADeletedSourceFileIsReportedOnceAndItsReturnReloads) {
    // A deleted file changes no modification time: the poll saw nothing and said nothing.
    gl::HotProgram hot(sources(), {"fill", {"fill.vert", "fill.frag"}});
    const GLuint good = hot.id();
    fs::remove(root / "common" / "colour.glsl");
    EXPECT_FALSE(hot.reloadIfChanged());
    EXPECT_EQ(hot.id(), good);
    EXPECT_NE(hot.error().find("common/colour.glsl"), std::string::npos) << "error: " << hot.error();
    EXPECT_FALSE(hot.reloadIfChanged());  // once, not every poll
    write("common/colour.glsl", "vec3 colour() { return vec3(0.5); }\n");
    EXPECT_TRUE(hot.reloadIfChanged());
    EXPECT_TRUE(hot.error().empty()) << hot.error();
}

TEST_F(ProgramTest, ReloadingOftenDeletesWhatItReplaced) {
    // Every forced rebuild replaces the program: the context holds one program and no shaders
    // whatever the number of reloads (the soak measures memory; this counts GL objects).
    gl::HotProgram hot(sources(), {"fill", {"fill.vert", "fill.frag"}});
    glUseProgram(0);  // a current program outlives its deletion
    const gl::LiveObjects before = gl::countLiveObjects(4096);
    for (int i = 0; i < 20; ++i) EXPECT_TRUE(hot.reloadIfChanged(true));
    EXPECT_EQ(gl::countLiveObjects(4096), before) << gl::describe(gl::countLiveObjects(4096));
    EXPECT_GE(before.programs, 1);
    EXPECT_EQ(before.shaders, 0);
}

TEST_F(ProgramTest, FirstBuildFailureThrows) {
    write("fill.frag", "void main() { syntax error }\n");
    EXPECT_THROW(gl::HotProgram(sources(), {"fill", {"fill.vert", "fill.frag"}}), gl::ShaderError);
}

TEST_F(ProgramTest, ContextIsOpenGL45Core) {
    EXPECT_NO_THROW(gl::requireGL45());
    EXPECT_NE(gl::rendererDescription().find("OpenGL"), std::string::npos);
}
