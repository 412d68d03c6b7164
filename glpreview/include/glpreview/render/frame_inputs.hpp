// What every GPU frame pass of a preview (beauty, localization, timing) reads from the graph and hands to the
// renderer: the effects add their resources here (in registry order), so the frame passes run after the passes that
// make them, the graph frees each after its last frame, and the renderer finds them on its blackboard.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/blackboard.hpp"

namespace metalfit::glpreview {

class GpuRenderer;

class FrameInputs {
public:
    // The frame reads `handle` and nothing more (an input that orders the passes, e.g. the scene's camera).
    template <class T>
    void read(graph::Handle<T> handle) {
        inputs_.push_back({[handle](graph::Builder& b) { b.read(handle); }, {}});
    }
    // The frame reads `handle` and finds its value on the renderer's blackboard under T and `name`.
    template <class T>
    void add(graph::Handle<T> handle, const std::string& name = {}) {
        inputs_.push_back(
            {[handle](graph::Builder& b) { b.read(handle); },
             [handle, name](GpuRenderer& gpu, graph::Resources& r) { frame_of(gpu).put(r.get(handle), name); }});
    }
    // The frame reads what `declare` declares and `bind` hands it to the renderer.
    void add(std::function<void(graph::Builder&)> declare, std::function<void(GpuRenderer&, graph::Resources&)> bind) {
        inputs_.push_back({std::move(declare), std::move(bind)});
    }
    void declare(graph::Builder& b) const {
        for (const Input& input : inputs_) input.declare(b);
    }
    void bind(GpuRenderer& gpu, graph::Resources& r) const {
        for (const Input& input : inputs_)
            if (input.bind) input.bind(gpu, r);
    }

private:
    static Blackboard& frame_of(GpuRenderer& gpu);
    struct Input {
        std::function<void(graph::Builder&)> declare;
        std::function<void(GpuRenderer&, graph::Resources&)> bind;
    };
    std::vector<Input> inputs_;
};

}  // namespace metalfit::glpreview
