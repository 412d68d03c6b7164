#include "glpreview/gl/gl_context.hpp"

#include "glpreview/gl/program_cache.hpp"
#include "libfit/base/number_text.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <sstream>

namespace metalfit::glpreview {
namespace {

std::string egl_error_text() {
    return "EGL error 0x" + hex_text(static_cast<unsigned>(eglGetError()), 4, HexLetters::lower);
}

template <typename F>
F egl_proc(const char* name) {
    return reinterpret_cast<F>(eglGetProcAddress(name));
}

// The first line of a shader info log, which names the line of the first error.
std::string first_line(const std::string& log) {
    const auto end = log.find('\n');
    std::string line = log.substr(0, end);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return line.empty() ? "(no info log)" : line;
}

// The first line of a shader's or a program's info log (glGetShaderiv/glGetShaderInfoLog or the program pair).
template <typename GetIv, typename GetLog>
std::string info_log(GLuint id, GetIv get_iv, GetLog get_log) {
    GLint length = 0;
    get_iv(id, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    get_log(id, length, nullptr, log.data());
    return first_line(log.c_str());
}

const char* stage_name(GLenum type) {
    switch (type) {
        case GL_VERTEX_SHADER: return "vertex";
        case GL_FRAGMENT_SHADER: return "fragment";
        case GL_COMPUTE_SHADER: return "compute";
        default: return "shader";
    }
}

}  // namespace

struct GlContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::string platform;
    ProgramCache programs;  // deleted while the context is still current (below)

    ~Impl() {
        programs = ProgramCache();
        release();
    }

    // Initialises `dpy` and makes a GL 4.5 core context current on it; returns "" or why it failed.
    std::string make_current(EGLDisplay dpy) {
        if (dpy == EGL_NO_DISPLAY) return "no display (" + egl_error_text() + ")";
        EGLint major = 0, minor = 0;
        if (!eglInitialize(dpy, &major, &minor)) return "eglInitialize failed (" + egl_error_text() + ")";
        display = dpy;
        if (!eglBindAPI(EGL_OPENGL_API)) return "eglBindAPI(EGL_OPENGL_API) failed (" + egl_error_text() + ")";
        const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                            EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!eglChooseConfig(dpy, config_attributes, &config, 1, &count) || count == 0) config = nullptr;
        const EGLint context_attributes[] = {
            EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, context_attributes);
        if (context == EGL_NO_CONTEXT) return "no OpenGL 4.5 core context (" + egl_error_text() + ")";
        if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
            return "eglMakeCurrent without a surface failed (" + egl_error_text() + ")";
        return {};
    }

    void release() {
        if (display == EGL_NO_DISPLAY) return;
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
        eglTerminate(display);
        context = EGL_NO_CONTEXT;
        display = EGL_NO_DISPLAY;
    }
};

bool is_software_renderer(std::string_view renderer) {
    for (const char* software : {"llvmpipe", "softpipe", "SwiftShader", "swrast"})
        if (renderer.find(software) != std::string_view::npos) return true;
    return false;
}

GlContext GlContext::create() {
    auto get_platform_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (!get_platform_display) throw GlError("EGL: eglGetPlatformDisplayEXT is not available (EGL_EXT_platform_base)");
    const char* chosen = std::getenv("GLPREVIEW_EGL_PLATFORM");
    const std::string platform = chosen ? chosen : "";
    if (!platform.empty() && platform != "device" && platform != "surfaceless")
        throw GlError("GLPREVIEW_EGL_PLATFORM=" + platform + ": not a platform (device or surfaceless)");
    const bool gpu_only = platform == "device";
    std::ostringstream failures;

    if (!gpu_only) {
        auto impl = std::make_unique<Impl>();
        const std::string surfaceless =
            impl->make_current(get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
        if (surfaceless.empty()) {
            impl->platform = "EGL surfaceless (Mesa)";
            return GlContext(std::move(impl));
        }
        failures << "surfaceless Mesa platform: " << surfaceless;
        impl->release();
        if (platform == "surfaceless")
            throw GlError("EGL: no headless OpenGL 4.5 core context (GLPREVIEW_EGL_PLATFORM=surfaceless): " +
                          failures.str());
    } else {
        failures << "surfaceless Mesa platform: skipped (GLPREVIEW_EGL_PLATFORM=device)";
    }

    auto query_devices = egl_proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    if (!query_devices) {
        failures << "; device platform: eglQueryDevicesEXT is not available";
        throw GlError("EGL: no headless OpenGL 4.5 core context: " + failures.str());
    }
    EGLDeviceEXT devices[16];
    EGLint device_count = 0;
    query_devices(16, devices, &device_count);
    for (EGLint i = 0; i < device_count; ++i) {
        auto candidate = std::make_unique<Impl>();
        const std::string why =
            candidate->make_current(get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
        const auto* renderer = why.empty() ? reinterpret_cast<const char*>(glGetString(GL_RENDERER)) : nullptr;
        if (why.empty() && gpu_only && is_software_renderer(renderer ? renderer : "")) {
            failures << "; device " << i << ": " << renderer << " is a software rasteriser";
            candidate->release();
            continue;
        }
        if (why.empty()) {
            candidate->platform = "EGL device";
            return GlContext(std::move(candidate));
        }
        failures << "; device " << i << ": " << why;
        candidate->release();
    }
    if (device_count == 0) failures << "; device platform: no EGL device";
    throw GlError(std::string("EGL: no headless OpenGL 4.5 core context") +
                  (gpu_only ? " on a GPU (GLPREVIEW_EGL_PLATFORM=device)" : "") + ": " + failures.str());
}

GlContext::GlContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlContext::GlContext(GlContext&&) noexcept = default;
GlContext& GlContext::operator=(GlContext&&) noexcept = default;
GlContext::~GlContext() = default;

const std::string& GlContext::platform() const { return impl_->platform; }
ProgramCache& GlContext::programs() { return impl_->programs; }

std::string GlContext::renderer() const {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return text ? text : "unknown";
}

std::string GlContext::version() const {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return text ? text : "unknown";
}

void check_gl(std::string_view what) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) return;
    while (glGetError() != GL_NO_ERROR) {}
    throw GlError(std::string(what) + ": GL error 0x" + hex_text(error, 4, HexLetters::lower));
}

gl::Program link_program(const std::vector<ShaderStage>& stages, std::string_view name) {
    gl::Program program = gl::create_program();
    std::vector<gl::Shader> shaders;  // deleted (detached by the link) when they go out of scope
    for (const ShaderStage& stage : stages) {
        gl::Shader& shader = shaders.emplace_back(gl::create_shader(stage.type));
        const char* text = stage.source.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok)
            throw GlError("shader '" + std::string(name) + "' (" + stage_name(stage.type) +
                          ") does not compile: " + info_log(shader.id(), glGetShaderiv, glGetShaderInfoLog));
        glAttachShader(program.id(), shader.id());
    }
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok)
        throw GlError("shader '" + std::string(name) +
                      "' does not link: " + info_log(program.id(), glGetProgramiv, glGetProgramInfoLog));
    return program;
}

gl::Program compile_compute_program(std::string_view source, std::string_view name) {
    return link_program({{GL_COMPUTE_SHADER, std::string(source)}}, name);
}

}  // namespace metalfit::glpreview
