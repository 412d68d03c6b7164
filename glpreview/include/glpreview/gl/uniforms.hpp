// Setting a program's uniforms by name (a name the program lacks is ignored, as GL does): vectors, colours, floats,
// integers, and a libfit model's parameters (u_param[k], one vec3 per parameter: R, G, B).
#pragma once

#include <string>

#include "glpreview/gl/gl.hpp"
#include "glpreview/scene/vec3.hpp"
#include "libfit/color/color.hpp"
#include "libfit/models/model.hpp"

namespace metalfit::glpreview {

inline void set_uniform(GLuint program, const char* name, Vec3 v) {
    glProgramUniform3f(program, glGetUniformLocation(program, name), static_cast<float>(v.x), static_cast<float>(v.y),
                       static_cast<float>(v.z));
}
inline void set_uniform(GLuint program, const char* name, const RGB& v) {
    glProgramUniform3f(program, glGetUniformLocation(program, name), static_cast<float>(v.r), static_cast<float>(v.g),
                       static_cast<float>(v.b));
}
inline void set_uniform(GLuint program, const char* name, float v) {
    glProgramUniform1f(program, glGetUniformLocation(program, name), v);
}
inline void set_uniform(GLuint program, const char* name, int v) {
    glProgramUniform1i(program, glGetUniformLocation(program, name), v);
}

// u_param[k] of `program` to parameter k's values for R, G and B, for every parameter the model has.
inline void set_model_parameters(GLuint program, const Model& model, const ModelParameters& params) {
    for (std::size_t k = 0; k < model.parameters().size(); ++k)
        set_uniform(program, ("u_param[" + std::to_string(k) + "]").c_str(),
                    Vec3{params[0][k], params[1][k], params[2][k]});
}

}  // namespace metalfit::glpreview
