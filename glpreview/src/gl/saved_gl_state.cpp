#include "glpreview/gl/saved_gl_state.hpp"

namespace metalfit::glpreview {

SavedGlState::SavedGlState() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    depth_test_ = glIsEnabled(GL_DEPTH_TEST);
    blend_ = glIsEnabled(GL_BLEND);
}

SavedGlState::~SavedGlState() {
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer_));
    glUseProgram(static_cast<GLuint>(program_));
    glBindVertexArray(static_cast<GLuint>(vertex_array_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    if (depth_test_)
        glEnable(GL_DEPTH_TEST);
    else
        glDisable(GL_DEPTH_TEST);
    if (blend_)
        glEnable(GL_BLEND);
    else
        glDisable(GL_BLEND);
}

}  // namespace metalfit::glpreview
