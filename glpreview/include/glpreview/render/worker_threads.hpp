// The CPU renderers' parallel loop: the same worker (which takes rows from a shared counter) on several threads, and
// the loop over an image's pixels built on it.
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace metalfit::glpreview {

// Runs `worker` on `threads` threads (0: all cores), the calling thread being one of them; returns when all finished.
template <class Worker>
void run_on_threads(int threads, const Worker& worker) {
    const int count = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::jthread> pool;
    for (int t = 1; t < count; ++t) pool.emplace_back(worker);
    worker();
}

// Calls `pixel(px, py, row)` for every pixel of a w × h image, whole rows shared out among `threads` threads: py
// counts from the bottom (as camera_ray takes it), row is the stored row (images are stored top row first).
template <class Pixel>
void for_each_pixel(int w, int h, int threads, const Pixel& pixel) {
    std::atomic<int> next_row{0};
    run_on_threads(threads, [&] {
        for (int py = next_row++; py < h; py = next_row++)
            for (int px = 0; px < w; ++px) pixel(px, py, h - 1 - py);
    });
}

}  // namespace metalfit::glpreview
