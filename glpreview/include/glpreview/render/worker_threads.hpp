// The CPU renderers' parallel loop: the same worker (which takes rows from a shared counter) on several threads.
#pragma once

#include <algorithm>
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

}  // namespace metalfit::glpreview
