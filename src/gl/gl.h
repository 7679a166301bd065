// The one place that includes the GL API (libepoxy resolves entry points for
// whichever context is current: GLX/EGL).
#pragma once

#include <epoxy/gl.h>
