// How many GL objects of each kind the current context holds, asked of the context itself
// (glIs* over the object names), so that a leak shows whoever created the objects: our RAII
// owners, Dear ImGui's backend, or anything else. For soak runs (planet bench --suite soak)
// and tests, not for every frame: it costs a few tens of milliseconds.
#pragma once

#include <string>

#include "gl/gl.h"

namespace planet::gl {

struct LiveObjects {
    int buffers = 0, textures = 0, framebuffers = 0, vertexArrays = 0, queries = 0;
    int programs = 0, shaders = 0;  // one name space in GL
    int total() const { return buffers + textures + framebuffers + vertexArrays + queries + programs + shaders; }
    bool operator==(const LiveObjects&) const = default;
};

// Counts the names for which glIs* answers true, from 1 up to `gapLimit` names past the
// highest live one of each kind (drivers hand out the lowest free names, so the live ones
// stay dense; the gap covers objects made and deleted in between).
LiveObjects countLiveObjects(GLuint gapLimit = 65536);

// "buffers 12, textures 40, ..." for logs and CSV headers.
std::string describe(const LiveObjects& objects);

}  // namespace planet::gl
