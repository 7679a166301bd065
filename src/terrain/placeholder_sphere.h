// The placeholder planet: an exact, ray-cast sphere of the planet's radius,
// drawn into the G-buffer through the same pass slot the terrain will take
// (shaders/terrain/placeholder_sphere.frag). It lets the whole frame -- depth
// range, lighting, tone mapping, profiling, headless rendering -- be built and
// tested before the projected grid exists.
#pragma once

#include "render/fullscreen_pass.h"
#include "scene/scene.h"

namespace planet {

class PlaceholderSphere {
public:
    explicit PlaceholderSphere(const gl::ShaderSources& sources)
        : pass_(sources, "placeholder_sphere", "terrain/placeholder_sphere.frag") {}

    // Writes normal, albedo, material and depth of the sphere into the bound G-buffer.
    void draw(const PlanetParams& planet) const;
    gl::HotProgram& program() { return pass_.program(); }

private:
    FullscreenPass pass_;
};

}  // namespace planet
