// KHR_debug: driver messages routed to the log, and one debug group per pass.
//
// DebugGroup is an RAII glPushDebugGroup/glPopDebugGroup pair, so a RenderDoc
// or apitrace capture reads by pass name ("terrain", "lighting", ...).
#pragma once

#include <string_view>

#include "gl/gl.h"

namespace planet::gl {

struct DebugMessages {
    int errors = 0;    // GL_DEBUG_TYPE_ERROR messages seen
    int warnings = 0;  // deprecated / undefined behaviour / portability / performance
};

// Installs the debug callback on the current context (a debug context gives
// complete messages). `sink` must outlive the context. Notifications are dropped.
void installDebugOutput(DebugMessages* sink, bool synchronous = true);

class DebugGroup {
public:
    explicit DebugGroup(std::string_view name) {
        glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()), name.data());
    }
    ~DebugGroup() { glPopDebugGroup(); }
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace planet::gl
