// A headless OpenGL 4.5 core context through EGL, for glint_gl: the surfaceless platform (Mesa,
// and NVIDIA's driver), else the first EGL device (EGL_EXT_platform_device), else the default
// display, starting from the platform named (a driver may offer one and fail in it); no window,
// no pbuffer (EGL_KHR_surfaceless_context), rendering into framebuffer objects. GL functions are
// the exports of glvnd's libOpenGL.so.0 (GL_GLEXT_PROTOTYPES).
#pragma once

#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <stdexcept>
#include <string>

namespace glint_gl {

class gl_context {
public:
    // first: "surfaceless", "device" or "default", the platform tried first.
    explicit gl_context(const std::string& first = "surfaceless") {
        display_ = open_display(first);
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor)) throw std::runtime_error("glint_gl: eglInitialize failed");
        if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("glint_gl: eglBindAPI(EGL_OPENGL_API) failed");
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        // EGL_KHR_no_config_context where the driver has it, else any OpenGL-renderable config.
        EGLConfig config = EGL_NO_CONFIG_KHR;
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
        if (context_ == EGL_NO_CONTEXT) {
            const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
            EGLint found = 0;
            if (!eglChooseConfig(display_, want, &config, 1, &found) || found < 1)
                throw std::runtime_error("glint_gl: no EGL config renders OpenGL");
            context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
        }
        if (context_ == EGL_NO_CONTEXT) throw std::runtime_error("glint_gl: eglCreateContext (OpenGL 4.5 core) failed");
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error("glint_gl: eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context)");
    }
    ~gl_context() {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
        eglReleaseThread();
    }
    gl_context(const gl_context&) = delete;
    gl_context& operator=(const gl_context&) = delete;

    // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)" or "NVIDIA H200/PCIe/SSE2".
    static std::string renderer() { return reinterpret_cast<const char*>(glGetString(GL_RENDERER)); }
    static std::string version() { return reinterpret_cast<const char*>(glGetString(GL_VERSION)); }

private:
    static EGLDisplay open_display(const std::string& first) {
        // The platforms in the order tried: the one named first, then surfaceless, device, default.
        const std::string all[3] = {"surfaceless", "device", "default"};
        std::string order[3] = {first, "", ""};
        int n = 1;
        for (const auto& name : all)
            if (name != first) order[n++] = name;
        for (const auto& name : order) {
            const EGLDisplay d = platform_display(name);
            if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
        }
        // The default display uninitialised: the constructor's eglInitialize reports the failure.
        const EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
        if (d == EGL_NO_DISPLAY) throw std::runtime_error("glint_gl: no EGL display (surfaceless, device or default)");
        return d;
    }

    static EGLDisplay platform_display(const std::string& name) {
        if (name == "surfaceless") return eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (name == "default") return eglGetDisplay(EGL_DEFAULT_DISPLAY);
        const auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        EGLDeviceEXT device[4];
        EGLint n = 0;
        if (!query_devices || !query_devices(4, device, &n) || n < 1) return EGL_NO_DISPLAY;
        return eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device[0], nullptr);
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace glint_gl
