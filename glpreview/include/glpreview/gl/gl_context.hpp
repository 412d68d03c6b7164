// A headless OpenGL 4.5 core context through EGL: no window system, no display server.
// Platforms, in order: EGL_PLATFORM_SURFACELESS_MESA (Mesa; llvmpipe without a GPU), then EGL_PLATFORM_DEVICE_EXT
// (the first EGL device that can make a GL 4.5 core context; GPU drivers). Rendering goes to framebuffer objects.
// GLPREVIEW_EGL_PLATFORM=device skips the surfaceless platform and takes the first EGL device whose renderer is not a
// software rasteriser (a GPU: scripts/gpu-bench.sh), or fails; =surfaceless takes that platform only.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "glpreview/gl/gl.hpp"
#include "glpreview/gl/objects.hpp"

namespace metalfit::glpreview {

// Any EGL or GL failure: a one-line message naming the call (and the shader, with its first error line).
class GlError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class ProgramCache;

// Whether GL_RENDERER names a software rasteriser (llvmpipe, softpipe, SwiftShader, swrast).
bool is_software_renderer(std::string_view renderer);

class GlContext {
public:
    // Creates the context and makes it current on the calling thread. Throws GlError naming what failed on every
    // platform tried.
    static GlContext create();

    GlContext(GlContext&&) noexcept;
    GlContext& operator=(GlContext&&) noexcept;
    ~GlContext();

    const std::string& platform() const;  // "EGL surfaceless (Mesa)" or "EGL device"
    std::string renderer() const;         // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version() const;          // GL_VERSION
    // The programs linked in this context, shared by every renderer made in it (glpreview/gl/program_cache.hpp).
    ProgramCache& programs();

private:
    struct Impl;
    explicit GlContext(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// Throws GlError("<what>: GL error 0x...") when glGetError reports one.
void check_gl(std::string_view what);

// A linked program from shader stages; GlError with the name, the stage and the info log's first line on failure.
struct ShaderStage {
    GLenum type;         // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
    std::string source;  // complete source, #version line included
};
gl::Program link_program(const std::vector<ShaderStage>& stages, std::string_view name);
gl::Program compile_compute_program(std::string_view source, std::string_view name);

}  // namespace metalfit::glpreview
