#include "gl/shader_source.h"

#include "util/file_util.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

namespace planet::gl {

namespace fs = std::filesystem;

namespace {

struct Expander {
    fs::path root;
    ExpandedShader out;
    std::vector<std::string> stack;  // files being expanded, for cycle detection

    int fileNumber(const std::string& file) {
        auto it = std::find(out.files.begin(), out.files.end(), file);
        if (it != out.files.end()) return static_cast<int>(it - out.files.begin());
        out.files.push_back(file);
        return static_cast<int>(out.files.size()) - 1;
    }

    static std::string readSource(const fs::path& path, const std::string& where) {
        if (const std::string why = whyNotReadableFile(path); !why.empty())
            throw ShaderError(where + "cannot open shader file '" + path.string() + "': " + why);
        std::ifstream in(path);
        if (!in) throw ShaderError(where + "cannot open shader file '" + path.string() + "'");
        std::ostringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }

    // Parses `#include "x"` (or <x>); returns false for any other line.
    static bool includeTarget(const std::string& line, std::string& target) {
        static const std::regex re(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"]\s*(//.*)?$)");
        std::smatch m;
        if (!std::regex_match(line, m, re)) return false;
        target = m[1];
        return true;
    }

    void expand(const std::string& file, const std::string& where) {
        if (std::find(stack.begin(), stack.end(), file) != stack.end())
            throw ShaderError(where + "include cycle through '" + file + "'");
        const bool seen = std::find(out.files.begin(), out.files.end(), file) != out.files.end();
        if (seen && !stack.empty()) return;  // implicit include guard
        const std::string source = readSource(root / file, where);
        const int number = fileNumber(file);
        stack.push_back(file);
        out.text += "#line 1 " + std::to_string(number) + "\n";
        std::istringstream lines(source);
        std::string line;
        for (int lineNo = 1; std::getline(lines, line); ++lineNo) {
            std::string target;
            if (!includeTarget(line, target)) {
                out.text += line + "\n";
                continue;
            }
            // Include paths are relative to the shaders root, like the program descriptions.
            expand(fs::path(target).lexically_normal().generic_string(), file + ":" + std::to_string(lineNo) + ": ");
            out.text += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(number) + "\n";
        }
        stack.pop_back();
    }
};

}  // namespace

ExpandedShader expandShader(const fs::path& root, const std::string& file, const std::string& preamble) {
    Expander e{root, {}, {}};
    e.out.text = preamble;
    if (!e.out.text.empty() && e.out.text.back() != '\n') e.out.text += '\n';
    e.expand(fs::path(file).lexically_normal().generic_string(), "");
    return e.out;
}

std::string translateShaderLog(const std::string& log, const std::vector<std::string>& files) {
    // Mesa "0:12(3):", glslang/AMD "0:12:", NVIDIA "0(12) :".
    static const std::regex re(R"((\d+):(\d+)\((\d+)\)|(\d+):(\d+)(?=:)|(\d+)\((\d+)\)(?= :))");
    auto name = [&](const std::string& number) {
        const auto i = static_cast<std::size_t>(std::stoul(number));
        return i < files.size() ? files[i] : "<string " + number + ">";
    };
    std::string result;
    auto begin = std::sregex_iterator(log.begin(), log.end(), re);
    std::size_t last = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        result += log.substr(last, static_cast<std::size_t>(m.position()) - last);
        if (m[1].matched) result += name(m[1]) + ":" + m[2].str() + ":" + m[3].str();
        else if (m[4].matched) result += name(m[4]) + ":" + m[5].str();
        else result += name(m[6]) + ":" + m[7].str();
        last = static_cast<std::size_t>(m.position() + m.length());
    }
    result += log.substr(last);
    return result;
}

std::string shaderStageName(const std::string& file) {
    const std::string ext = fs::path(file).extension().string();
    for (const char* stage : {"vert", "tesc", "tese", "geom", "frag", "comp"})
        if (ext == std::string(".") + stage) return stage;
    return {};
}

}  // namespace planet::gl
