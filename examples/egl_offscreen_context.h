// SPDX-License-Identifier: Apache-2.0
// An OpenGL 3.3 core context without a window or a display, from EGL: Mesa's surfaceless
// platform first (any machine with libegl-mesa0: software rendering with llvmpipe, no X
// server, no GPU), then the default display (a GPU driver's EGL). Header-only, through
// libepoxy; shared by the viewer's --headless mode (examples/viewer/run_headless.cpp) and
// the GPU upload benchmark (bench/upload_bench.cpp).
#pragma once

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <string>

namespace enteron_examples {

class EglOffscreenContext {
public:
    EglOffscreenContext() = default;
    EglOffscreenContext(const EglOffscreenContext&) = delete;
    EglOffscreenContext& operator=(const EglOffscreenContext&) = delete;
    ~EglOffscreenContext() {
        if (display_ == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    // Makes the context and makes it current on the calling thread. False with `error`
    // saying why when EGL cannot.
    bool create(std::string& error) {
        if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
            display_ = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY) display_ = eglGetDisplay(EGL_DEFAULT_DISPLAY);
        EGLint major = 0, minor = 0;
        if (display_ == EGL_NO_DISPLAY || eglInitialize(display_, &major, &minor) != EGL_TRUE) {
            error = "EGL has no display here (eglInitialize failed, EGL error 0x" + hex(eglGetError()) +
                    "); Mesa's software renderer for EGL is in libegl-mesa0";
            display_ = EGL_NO_DISPLAY;
            return false;
        }
        if (!epoxy_has_egl_extension(display_, "EGL_KHR_surfaceless_context")) {
            error = "EGL on this display cannot make a context current without a surface";
            return false;
        }
        const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configs = 0;
        if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE ||
            eglChooseConfig(display_, config_attributes, &config, 1, &configs) != EGL_TRUE || configs == 0) {
            error = "EGL offers no desktop OpenGL configuration";
            return false;
        }
        const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                             EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                             EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
        if (context_ == EGL_NO_CONTEXT || eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE) {
            error = "EGL cannot make an OpenGL 3.3 core context (error 0x" + hex(eglGetError()) + ")";
            return false;
        }
        renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        return true;
    }

    // GL_RENDERER of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    const std::string& renderer() const { return renderer_; }

private:
    static std::string hex(EGLint value) {
        char text[16];
        std::snprintf(text, sizeof text, "%x", static_cast<unsigned>(value));
        return text;
    }
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    std::string renderer_;
};

}  // namespace enteron_examples
