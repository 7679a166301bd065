#include "gl/context.h"

#include <epoxy/egl.h>
#include <cstdio>
#include <vector>

#include "gl/gl.h"

namespace planet::gl {

namespace {

struct Attempt {
    EGLDisplay display;
    const char* platform;
};

std::vector<Attempt> candidateDisplays() {
    std::vector<Attempt> out;
    const bool clientExts = epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base");
    if (clientExts && epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") &&
        epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                // Mesa lists a software device too; the surfaceless attempt below covers it.
                const char* exts = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
                if (exts && std::string(exts).find("EGL_MESA_device_software") != std::string::npos) continue;
                out.push_back({eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr), "EGL device"});
            }
        }
    }
    if (clientExts && epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
        out.push_back({eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                       "EGL surfaceless (Mesa)"});
    out.push_back({eglGetDisplay(EGL_DEFAULT_DISPLAY), "EGL default display"});
    return out;
}

EGLContext createCoreContext(EGLDisplay display, bool debug) {
    if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    eglChooseConfig(display, configAttribs, &config, 1, &count);
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
    // Surfaceless contexts may have no config at all (EGL_KHR_no_config_context).
    return eglCreateContext(display, count > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttribs);
}

}  // namespace

HeadlessContext::HeadlessContext(bool debug) {
    std::string tried;
    for (const Attempt& a : candidateDisplays()) {
        if (a.display == EGL_NO_DISPLAY) continue;
        EGLint major = 0, minor = 0;
        if (!eglInitialize(a.display, &major, &minor)) {
            tried += std::string("\n  ") + a.platform + ": eglInitialize failed";
            continue;
        }
        EGLContext ctx = createCoreContext(a.display, debug);
        if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(a.display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
            char code[16];
            std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
            tried += std::string("\n  ") + a.platform + ": no OpenGL 4.5 core context (EGL error " + code + ")";
            if (ctx != EGL_NO_CONTEXT) eglDestroyContext(a.display, ctx);
            eglTerminate(a.display);
            continue;
        }
        display_ = a.display;
        context_ = ctx;
        platform_ = a.platform;
        try {
            requireGL45();
        } catch (...) {
            release();  // the destructor does not run for a throwing constructor
            throw;
        }
        return;
    }
    throw ContextError("could not create a headless OpenGL 4.5 core context through EGL:" +
                       (tried.empty() ? std::string("\n  no EGL display found") : tried) +
                       "\n  (install Mesa's libegl-mesa0 and libgl1-mesa-dri, or a GPU driver with EGL)");
}

HeadlessContext::~HeadlessContext() { release(); }

void HeadlessContext::release() {
    if (!display_) return;
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
    display_ = context_ = nullptr;
}

void requireGL45() {
    const int version = epoxy_gl_version();  // e.g. 45
    if (version < 45 || epoxy_is_desktop_gl() == 0)
        throw ContextError("OpenGL 4.5 core is required, but this context offers " + rendererDescription() +
                           " (on Mesa, try MESA_GL_VERSION_OVERRIDE=4.5 only for debugging)");
}

std::string rendererDescription() {
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return str(GL_RENDERER) + " (" + str(GL_VENDOR) + "), OpenGL " + str(GL_VERSION);
}

bool softwareRenderer(std::string_view glRenderer) {
    for (const char* software : {"llvmpipe", "softpipe", "swrast"})
        if (glRenderer.find(software) != std::string_view::npos) return true;
    return false;
}

}  // namespace planet::gl
