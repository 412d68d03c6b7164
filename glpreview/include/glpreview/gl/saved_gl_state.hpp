// The GL state a pass that draws on its own changes (the framebuffer, the program, the vertex array, the viewport,
// the depth test, blending), saved when made and given back when destroyed: an effect that makes its maps in the
// middle of a frame (the first draw that needs them, without a graph) leaves the frame as it found it, even when it
// throws.
#pragma once

#include "glpreview/gl/gl.hpp"

namespace metalfit::glpreview {

class SavedGlState {
public:
    SavedGlState();
    ~SavedGlState();
    SavedGlState(const SavedGlState&) = delete;
    SavedGlState& operator=(const SavedGlState&) = delete;

private:
    GLint framebuffer_ = 0, program_ = 0, vertex_array_ = 0;
    GLint viewport_[4] = {0, 0, 0, 0};
    GLboolean depth_test_ = GL_FALSE, blend_ = GL_FALSE;
};

}  // namespace metalfit::glpreview
