// What every GPU frame pass of a preview (beauty, localization, timing) reads from the graph and hands to the
// renderer's blackboard: the effects add their resources here, so the frame passes run after the passes that make
// them and the graph frees each after its last frame.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "glpreview/graph/pass_graph.hpp"
#include "glpreview/render/blackboard.hpp"

namespace metalfit::glpreview {

class FrameInputs {
public:
    // The frame reads `handle` and finds its value on the blackboard under T and `name`.
    template <class T>
    void add(graph::Handle<T> handle, const std::string& name = {}) {
        inputs_.push_back({[handle](graph::Builder& b) { b.read(handle); },
                           [handle, name](Blackboard& frame, graph::Resources& r) { frame.put(r.get(handle), name); }});
    }
    void declare(graph::Builder& b) const {
        for (const Input& input : inputs_) input.declare(b);
    }
    void bind(Blackboard& frame, graph::Resources& r) const {
        for (const Input& input : inputs_) input.bind(frame, r);
    }

private:
    struct Input {
        std::function<void(graph::Builder&)> declare;
        std::function<void(Blackboard&, graph::Resources&)> bind;
    };
    std::vector<Input> inputs_;
};

}  // namespace metalfit::glpreview
