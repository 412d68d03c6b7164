// Linked GL programs by their complete sources, for the life of one GL context: the renderers of several scenes in
// one context (glpreview --batch, a library of materials) compile and link each distinct program once. A program's
// uniforms are not part of the key: whoever takes a program sets the uniforms it needs (GpuRenderer does on first use).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "glpreview/gl/gl_context.hpp"

namespace metalfit::glpreview {

class ProgramCache {
public:
    // The program of these stages, linked on the first request for the same stages; `name` names it in errors.
    GLuint program(const std::vector<ShaderStage>& stages, std::string_view name);

    std::size_t size() const { return programs_.size(); }  // distinct programs linked so far

private:
    std::map<std::string, gl::Program> programs_;  // by the stages' types and sources
};

}  // namespace metalfit::glpreview
