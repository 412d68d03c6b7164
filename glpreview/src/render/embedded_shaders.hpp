// The embedded text of glpreview/shaders/<name> (generated at build time; see CMakeLists.txt).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "glpreview/gl/gl_context.hpp"
#include "shader_sources.hpp"

namespace metalfit::glpreview {

inline std::string_view shader_text(std::string_view name) {
    for (const auto& [file, text] : detail::kPreviewShaders)
        if (file == name) return text;
    throw std::out_of_range("no embedded preview shader '" + std::string(name) + "'");
}

// The vertex stage of every full-screen pass: one triangle covering the viewport.
inline ShaderStage fullscreen_vertex_stage() {
    return {GL_VERTEX_SHADER, "#version 450 core\n" + std::string(shader_text("fullscreen.vert"))};
}

}  // namespace metalfit::glpreview
