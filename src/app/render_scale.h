// The explorer's render scale: the frame is rendered at a fraction of the window's
// pixels and shown scaled up (bilinear), as the viewports of other 3D tools do when the
// full resolution is too slow to fly with. Stills (`planet render`) always render at
// their --size.
#pragma once

#include <optional>
#include <string>

#include <glm/vec2.hpp>

namespace planet {

// "auto" keeps a software renderer's frame at about this many pixels (320x180): there a
// frame's cost grows with its pixels (0.26-0.68 s at 320x180 on two cores, llvmpipe, in
// the ground, beach and sea views), and the window must stay interactive.
inline constexpr double kSoftwareFramePixels = 320.0 * 180.0;
inline constexpr double kMinRenderScale = 0.1;

// A --render-scale choice: "auto" (nullopt) or a number in [0.1, 1]. Throws
// std::invalid_argument naming the accepted forms.
std::optional<double> parseRenderScale(const std::string& choice);

// The scale used for a window of `window` pixels: the explicit one, or for auto 1 on a
// hardware renderer and, on a software one (gl/context.h: softwareRenderer), the
// largest scale whose frame has at most kSoftwareFramePixels pixels.
double renderScaleFor(const std::optional<double>& chosen, const std::string& glRenderer, glm::ivec2 window);

// The frame's size at `scale`: each side rounded, at least one pixel.
glm::ivec2 scaledSize(glm::ivec2 window, double scale);

}  // namespace planet
