// GpuRenderer's diagnostics and timing: the localization frame, the captured cube read back, frames timed.
#include "frame_timing.hpp"
#include "glpreview/render/gpu_renderer.hpp"

namespace metalfit::glpreview {

Image GpuRenderer::render_localization() {
    draw_frame(true);
    return read_frame();
}

std::vector<double> GpuRenderer::time_frames(int frames) {
    std::vector<double> ms;
    draw_frame();  // compiles every variant before timing
    glFinish();
    for (int i = 0; i < frames; ++i) ms.push_back(finished_ms([&] { draw_frame(); }));
    check_gl("timing frames");
    return ms;
}

std::vector<float> GpuRenderer::read_cube_face(int face) const {
    const int n = scene_.environment.cube_size;
    std::vector<float> texels(static_cast<std::size_t>(n) * n * 4);
    glGetTextureSubImage(cube_->texture.id(), 0, 0, 0, face, n, n, 1, GL_RGBA, GL_FLOAT,
                         static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
    check_gl("reading a cube face");
    return texels;
}

}  // namespace metalfit::glpreview
