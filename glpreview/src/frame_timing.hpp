// Timing GL work: wall-clock milliseconds of a call followed by glFinish, and the median of such times.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

#include "glpreview/gl.hpp"

namespace metalfit::glpreview {

// Milliseconds from the call of `work` until the GL has finished everything it issued.
template <typename Work>
double finished_ms(Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// 0 for no samples.
inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace metalfit::glpreview
