#include "gl_compute.hpp"

#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

#include <dlfcn.h>
#include <stdexcept>

#include <glint/glsl.hpp>

namespace glint_test {

struct gl_compute::impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    PFNGLGETSTRINGPROC GetString = nullptr;
    PFNGLGETERRORPROC GetError = nullptr;
    PFNGLCREATESHADERPROC CreateShader = nullptr;
    PFNGLSHADERSOURCEPROC ShaderSource = nullptr;
    PFNGLCOMPILESHADERPROC CompileShader = nullptr;
    PFNGLGETSHADERIVPROC GetShaderiv = nullptr;
    PFNGLGETSHADERINFOLOGPROC GetShaderInfoLog = nullptr;
    PFNGLDELETESHADERPROC DeleteShader = nullptr;
    PFNGLCREATEPROGRAMPROC CreateProgram = nullptr;
    PFNGLATTACHSHADERPROC AttachShader = nullptr;
    PFNGLLINKPROGRAMPROC LinkProgram = nullptr;
    PFNGLGETPROGRAMIVPROC GetProgramiv = nullptr;
    PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog = nullptr;
    PFNGLDELETEPROGRAMPROC DeleteProgram = nullptr;
    PFNGLUSEPROGRAMPROC UseProgram = nullptr;
    PFNGLGENBUFFERSPROC GenBuffers = nullptr;
    PFNGLDELETEBUFFERSPROC DeleteBuffers = nullptr;
    PFNGLBINDBUFFERPROC BindBuffer = nullptr;
    PFNGLBUFFERDATAPROC BufferData = nullptr;
    PFNGLBINDBUFFERBASEPROC BindBufferBase = nullptr;
    PFNGLGETBUFFERSUBDATAPROC GetBufferSubData = nullptr;
    PFNGLDISPATCHCOMPUTEPROC DispatchCompute = nullptr;
    PFNGLMEMORYBARRIERPROC MemoryBarrier = nullptr;
    PFNGLFINISHPROC Finish = nullptr;
    PFNGLGENTEXTURESPROC GenTextures = nullptr;
    PFNGLDELETETEXTURESPROC DeleteTextures = nullptr;
    PFNGLBINDTEXTUREPROC BindTexture = nullptr;
    PFNGLACTIVETEXTUREPROC ActiveTexture = nullptr;
    PFNGLTEXIMAGE2DPROC TexImage2D = nullptr;
    PFNGLTEXPARAMETERIPROC TexParameteri = nullptr;
    PFNGLTEXIMAGE3DPROC TexImage3D = nullptr;
    std::vector<unsigned> programs;

    template <class F>
    void load(F& f, const char* name) {
        f = reinterpret_cast<F>(eglGetProcAddress(name));
        if (!f) throw std::runtime_error(std::string("gl_compute: eglGetProcAddress(") + name + ") failed");
    }
};

#if defined(__SANITIZE_ADDRESS__)
namespace {
// eglTerminate unloads Mesa's DRI driver, after which LeakSanitizer cannot name the module of the
// driver's own leftovers, and the suppressions below cannot match them. Loading it first with
// RTLD_NODELETE keeps it mapped to the end (Mesa's dlopen then finds the same object).
void keep_dri_driver_loaded() {
    std::string dirs = std::getenv("LIBGL_DRIVERS_PATH") ? std::getenv("LIBGL_DRIVERS_PATH") : "";
    dirs += ":/usr/lib/x86_64-linux-gnu/dri:/usr/lib/aarch64-linux-gnu/dri:/usr/lib/dri";
    for (std::size_t start = 0; start < dirs.size();) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const std::string path = dirs.substr(start, end - start) + "/swrast_dri.so";
        if (end > start && dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL | RTLD_NODELETE)) return;
        start = end + 1;
    }
}
}  // namespace
#endif

gl_compute::gl_compute() : impl_(new impl) {
    // Software rendering on the CPU: the same llvmpipe here and in CI, whatever GPU is present.
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
#if defined(__SANITIZE_ADDRESS__)
    keep_dri_driver_loaded();
#endif
    impl& g = *impl_;
    g.display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (g.display == EGL_NO_DISPLAY) throw std::runtime_error("gl_compute: no EGL surfaceless display (is libegl-mesa0 installed?)");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(g.display, &major, &minor)) throw std::runtime_error("gl_compute: eglInitialize failed");
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error("gl_compute: eglBindAPI(EGL_OPENGL_API) failed");
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    // EGL_KHR_no_config_context and EGL_KHR_surfaceless_context: no window, no pbuffer.
    g.context = eglCreateContext(g.display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, context_attributes);
    if (g.context == EGL_NO_CONTEXT) throw std::runtime_error("gl_compute: eglCreateContext (OpenGL 4.5 core) failed");
    if (!eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, g.context))
        throw std::runtime_error("gl_compute: eglMakeCurrent (surfaceless) failed");
    g.load(g.GetString, "glGetString");
    g.load(g.GetError, "glGetError");
    g.load(g.CreateShader, "glCreateShader");
    g.load(g.ShaderSource, "glShaderSource");
    g.load(g.CompileShader, "glCompileShader");
    g.load(g.GetShaderiv, "glGetShaderiv");
    g.load(g.GetShaderInfoLog, "glGetShaderInfoLog");
    g.load(g.DeleteShader, "glDeleteShader");
    g.load(g.CreateProgram, "glCreateProgram");
    g.load(g.AttachShader, "glAttachShader");
    g.load(g.LinkProgram, "glLinkProgram");
    g.load(g.GetProgramiv, "glGetProgramiv");
    g.load(g.GetProgramInfoLog, "glGetProgramInfoLog");
    g.load(g.DeleteProgram, "glDeleteProgram");
    g.load(g.UseProgram, "glUseProgram");
    g.load(g.GenBuffers, "glGenBuffers");
    g.load(g.DeleteBuffers, "glDeleteBuffers");
    g.load(g.BindBuffer, "glBindBuffer");
    g.load(g.BufferData, "glBufferData");
    g.load(g.BindBufferBase, "glBindBufferBase");
    g.load(g.GetBufferSubData, "glGetBufferSubData");
    g.load(g.DispatchCompute, "glDispatchCompute");
    g.load(g.MemoryBarrier, "glMemoryBarrier");
    g.load(g.Finish, "glFinish");
    g.load(g.GenTextures, "glGenTextures");
    g.load(g.DeleteTextures, "glDeleteTextures");
    g.load(g.BindTexture, "glBindTexture");
    g.load(g.ActiveTexture, "glActiveTexture");
    g.load(g.TexImage2D, "glTexImage2D");
    g.load(g.TexImage3D, "glTexImage3D");
    g.load(g.TexParameteri, "glTexParameteri");
}

unsigned gl_compute::texture_rgba32f(int width, int height, const std::vector<float>& rgba) {
    impl& g = *impl_;
    if (rgba.size() != 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
        throw std::runtime_error("gl_compute: texture data size does not match " + std::to_string(width) + " x " + std::to_string(height));
    GLuint tex = 0;
    g.GenTextures(1, &tex);
    g.ActiveTexture(GL_TEXTURE0);
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, rgba.data());
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    if (g.GetError() != GL_NO_ERROR) throw std::runtime_error("gl_compute: creating the texture failed");
    return tex;
}

unsigned gl_compute::texture_array_rgba32f(int width, int height, int layers, const std::vector<float>& rgba) {
    impl& g = *impl_;
    if (rgba.size() != 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(layers))
        throw std::runtime_error("gl_compute: texture array data size does not match " + std::to_string(width) + " x " + std::to_string(height) + " x " +
                                 std::to_string(layers));
    GLuint tex = 0;
    g.GenTextures(1, &tex);
    g.ActiveTexture(GL_TEXTURE0);
    g.BindTexture(GL_TEXTURE_2D_ARRAY, tex);
    g.TexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, width, height, layers, 0, GL_RGBA, GL_FLOAT, rgba.data());
    g.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    g.TexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    if (g.GetError() != GL_NO_ERROR) throw std::runtime_error("gl_compute: creating the texture array failed");
    return tex;
}

void gl_compute::delete_texture(unsigned texture) {
    GLuint t = texture;
    impl_->DeleteTextures(1, &t);
}

gl_compute::~gl_compute() {
    impl& g = *impl_;
    for (unsigned p : g.programs) g.DeleteProgram(p);
    eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (g.context != EGL_NO_CONTEXT) eglDestroyContext(g.display, g.context);
    eglTerminate(g.display);
    eglReleaseThread();
}

std::string gl_compute::renderer() const {
    return reinterpret_cast<const char*>(impl_->GetString(GL_RENDERER));
}

std::string gl_compute::version() const {
    return reinterpret_cast<const char*>(impl_->GetString(GL_VERSION));
}

unsigned gl_compute::program(const std::string& source) {
    impl& g = *impl_;
    GLuint shader = g.CreateShader(GL_COMPUTE_SHADER);
    const char* text = source.c_str();
    g.ShaderSource(shader, 1, &text, nullptr);
    g.CompileShader(shader);
    GLint ok = 0;
    g.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[8192] = {0};
        g.GetShaderInfoLog(shader, sizeof log, nullptr, log);
        g.DeleteShader(shader);
        throw std::runtime_error(std::string("gl_compute: compute shader does not compile:\n") + log);
    }
    GLuint prog = g.CreateProgram();
    g.AttachShader(prog, shader);
    g.LinkProgram(prog);
    g.DeleteShader(shader);
    g.GetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[8192] = {0};
        g.GetProgramInfoLog(prog, sizeof log, nullptr, log);
        g.DeleteProgram(prog);
        throw std::runtime_error(std::string("gl_compute: compute program does not link:\n") + log);
    }
    g.programs.push_back(prog);
    return prog;
}

std::vector<std::uint32_t> gl_compute::run(unsigned prog, const std::vector<std::vector<std::uint32_t>>& inputs,
                                           std::size_t output_words, std::size_t invocations) {
    impl& g = *impl_;
    std::vector<GLuint> buffers(inputs.size() + 1);
    g.GenBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        g.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffers[i]);
        // A zero-sized SSBO is an error; keep one word so that .length() is defined.
        std::vector<std::uint32_t> data = inputs[i].empty() ? std::vector<std::uint32_t>(1) : inputs[i];
        g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(data.size() * 4), data.data(), GL_STATIC_DRAW);
        g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(i), buffers[i]);
    }
    GLuint out = buffers.back();
    std::vector<std::uint32_t> result(output_words);
    g.BindBuffer(GL_SHADER_STORAGE_BUFFER, out);
    g.BufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(output_words, 1) * 4), nullptr,
                 GL_DYNAMIC_READ);
    g.BindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(inputs.size()), out);
    g.UseProgram(prog);
    std::size_t groups = (invocations + local_size - 1) / local_size;
    if (groups > max_groups) groups = max_groups;
    if (groups == 0) groups = 1;
    g.DispatchCompute(static_cast<GLuint>(groups), 1, 1);
    g.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    g.BindBuffer(GL_SHADER_STORAGE_BUFFER, out);
    if (output_words) g.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(output_words * 4), result.data());
    g.Finish();
    GLenum err = g.GetError();
    g.DeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (err != GL_NO_ERROR) throw std::runtime_error("gl_compute: GL error " + std::to_string(err) + " during dispatch");
    return result;
}

std::string shader_header(const std::vector<std::string>& kernel_files) {
    std::string s = "#version 450\nlayout(local_size_x = " + std::to_string(local_size) + ") in;\n";
    s += glint::glsl_source("prelude.glsl");
    for (const std::string& f : kernel_files) s += (f.rfind("#define ", 0) == 0) ? f + "\n" : std::string(glint::glsl_source(f));
    return s;
}

std::int64_t ulp_distance(float a, float b) {
    if (std::isnan(a) || std::isnan(b)) return (std::isnan(a) && std::isnan(b)) ? 0 : INT64_MAX;
    auto ordered = [](float f) {
        std::int32_t i;
        std::memcpy(&i, &f, 4);
        // Map the sign-magnitude bit pattern to a monotone integer line (+0 and -0 coincide).
        return i < 0 ? static_cast<std::int64_t>(INT32_MIN) - i : static_cast<std::int64_t>(i);
    };
    std::int64_t d = ordered(a) - ordered(b);
    return d < 0 ? -d : d;
}

}  // namespace glint_test

#if defined(__SANITIZE_ADDRESS__)
// LeakSanitizer: Mesa's llvmpipe and LLVM's JIT keep allocations alive past exit; they are not
// glint's and not the harness's.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libLLVM\nleak:libgallium\nleak:swrast_dri\nleak:libEGL_mesa\nleak:libglapi\nleak:libdrm\n";
}
#endif
