// Timing GL work: wall-clock milliseconds of a call followed by glFinish (statistics: libfit/base/sample_statistics.hpp).
#pragma once

#include <chrono>
#include <vector>

#include "glpreview/gl/gl.hpp"
#include "libfit/base/sample_statistics.hpp"

namespace metalfit::glpreview {

// Milliseconds from the call of `work` until the GL has finished everything it issued.
template <typename Work>
double finished_ms(Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace metalfit::glpreview
