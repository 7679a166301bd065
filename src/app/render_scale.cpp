#include "app/render_scale.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "gl/context.h"

namespace planet {

std::optional<double> parseRenderScale(const std::string& choice) {
    if (choice == "auto") return std::nullopt;
    const auto fail = [&] {
        return std::invalid_argument("--render-scale must be auto or a number from 0.1 to 1 (the share of the "
                                     "window's width and height rendered), not '" + choice + "'");
    };
    std::size_t used = 0;
    double scale = 0.0;
    try {
        scale = std::stod(choice, &used);
    } catch (const std::exception&) {
        throw fail();
    }
    if (used != choice.size() || !(scale >= kMinRenderScale && scale <= 1.0)) throw fail();
    return scale;
}

double renderScaleFor(const std::optional<double>& chosen, const std::string& glRenderer, glm::ivec2 window) {
    if (chosen) return *chosen;
    if (!gl::softwareRenderer(glRenderer) || window.x <= 0 || window.y <= 0) return 1.0;
    const double pixels = static_cast<double>(window.x) * window.y;
    return std::clamp(std::sqrt(kSoftwareFramePixels / pixels), kMinRenderScale, 1.0);
}

glm::ivec2 scaledSize(glm::ivec2 window, double scale) {
    return {std::max(1, static_cast<int>(std::lround(window.x * scale))),
            std::max(1, static_cast<int>(std::lround(window.y * scale)))};
}

}  // namespace planet
