// Shared pieces for tests that need GL: one headless EGL context per test
// suite (Mesa surfaceless on CI), and the repository's data paths.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/session.h"
#include "gl/context.h"
#include "gl/debug.h"
#include "render/readback.h"
#include "test_util.h"

namespace planet::test {

// The source tree, or PLANET_ROOT where it is set (as the planet executable does), so that a
// copied tree of changed shaders can be tried without touching the one others render from.
inline DataPaths repoPaths() {
    const char* root = std::getenv("PLANET_ROOT");
    return DataPaths{root != nullptr && *root != '\0' ? root : PLANET_SOURCE_DIR};
}

class GLTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        // No skip: a missing GL context is a failure, CI must be able to run these.
        context_ = std::make_unique<gl::HeadlessContext>(true);
        gl::installDebugOutput(&messages_);
    }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override { messages_ = {}; }  // one test's GL errors must not fail the next
    void TearDown() override { EXPECT_EQ(messages_.errors, 0) << "GL errors reported through KHR_debug"; }

    static inline std::unique_ptr<gl::HeadlessContext> context_;
    static inline gl::DebugMessages messages_;
};

inline bool allFinite(const ImageRGBAF& image) {
    for (float v : image.pixels)
        if (!std::isfinite(v)) return false;
    return true;
}

inline const float* pixelAt(const ImageRGBAF& image, int x, int y) {
    return &image.pixels[(static_cast<std::size_t>(y) * image.width + x) * 4];
}

// World direction of the view ray through the centre of pixel (x, imageRow) of an image of
// `size` (rows from the top, as read back), the camera's own projection.
inline glm::dvec3 pixelRay(const Camera& camera, glm::ivec2 size, int x, int imageRow) {
    const double aspect = double(size.x) / size.y;
    const int glRow = size.y - 1 - imageRow;
    const glm::dvec2 ndc((x + 0.5) / size.x * 2 - 1, (glRow + 0.5) / size.y * 2 - 1);
    const glm::dvec4 v = glm::inverse(camera.clipFromView(aspect)) * glm::dvec4(ndc, 0.5, 1.0);
    return glm::normalize(camera.worldFromView() * glm::normalize(glm::dvec3(v) / v.w));
}

// A copy of the repository's shader tree in a TempDir named by `name` (its own per process: CTest
// runs tests side by side, and two of them may ask for the same tree), kept until the test program
// ends, with `from` replaced by `to` in the shader `file` (e.g. a #define switch turned off), for a
// test that renders a scene with and without one piece. Fails the test when `from` is not in the file.
inline std::filesystem::path shadersWith(const std::string& name, const std::string& file, const std::string& from,
                                         const std::string& to) {
    namespace fs = std::filesystem;
    static std::vector<std::unique_ptr<TempDir>> trees;  // removed when the program ends
    trees.push_back(std::make_unique<TempDir>(name));
    const fs::path root = trees.back()->path;
    fs::copy(repoPaths().shaders(), root / "shaders", fs::copy_options::recursive);
    const fs::path path = root / "shaders" / file;
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    std::string source = text.str();
    const std::size_t at = source.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' is gone from " << path;
    if (at != std::string::npos) source.replace(at, from.size(), to);
    std::ofstream(path) << source;
    return root / "shaders";
}

// A copy of the shader tree (as shadersWith) whose fragment shader `file` counts its own
// invocations: its main() renamed and called from a new main() that first adds 1 to the
// InvocationCounter's buffer; with `earlyTests` false also its `layout(early_fragment_tests) in;`
// taken out (a test of the early stencil test: llvmpipe tests the stencil after a shader that
// writes memory, so that copy runs on every pixel the draw covers).
inline constexpr GLuint kInvocationCountBinding = 15;  // a shader storage binding the frame leaves free
// InvocationCounter's buffer as a shader copy declares it (its count: `testInvocations`).
inline std::string invocationCountDeclaration() {
    return "layout(std430, binding = " + std::to_string(kInvocationCountBinding) +
           ") buffer TestCount { uint testInvocations; };\n";
}
inline std::filesystem::path countingShaders(const std::string& name, const std::string& file, bool earlyTests) {
    namespace fs = std::filesystem;
    const fs::path root = shadersWith(name, file, "void main() {", "void countedMain() {");
    std::stringstream read;
    read << std::ifstream(root / file).rdbuf();
    std::string text = read.str();
    const std::string early = "layout(early_fragment_tests) in;";
    if (!earlyTests) {
        const std::size_t at = text.find(early);
        EXPECT_NE(at, std::string::npos) << "'" << early << "' is gone from " << file;
        if (at != std::string::npos) text.erase(at, early.size());
    }
    std::ofstream(root / file) << text << invocationCountDeclaration()
                               << "void main() {\n    atomicAdd(testInvocations, 1u);\n    countedMain();\n}\n";
    return root;
}

// The buffer countingShaders' programs add to, bound at kInvocationCountBinding by reset().
class InvocationCounter {
public:
    InvocationCounter() { glNamedBufferStorage(buffer_.id(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT); }
    void reset() const {
        const GLuint zero = 0;
        glNamedBufferSubData(buffer_.id(), 0, sizeof zero, &zero);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInvocationCountBinding, buffer_.id());
    }
    long long read() const {
        GLuint n = 0;
        glGetNamedBufferSubData(buffer_.id(), 0, sizeof n, &n);
        return static_cast<long long>(n);
    }

private:
    gl::Buffer buffer_;
};

// A depth-stencil (or depth) texture's depth and stencil, `size` pixels, rows from the bottom.
inline std::vector<float> readDepth(const gl::Texture& texture, glm::ivec2 size) {
    std::vector<float> depth(static_cast<std::size_t>(size.x) * size.y);
    glGetTextureImage(texture.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(depth.size() * sizeof(float)),
                      depth.data());
    return depth;
}
inline std::vector<GLubyte> readStencil(const gl::Texture& texture, glm::ivec2 size) {
    std::vector<GLubyte> stencil(static_cast<std::size_t>(size.x) * size.y);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);  // rows of any width, a byte a pixel
    glGetTextureImage(texture.id(), 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, static_cast<GLsizei>(stencil.size()),
                      stencil.data());
    return stencil;
}


}  // namespace planet::test
