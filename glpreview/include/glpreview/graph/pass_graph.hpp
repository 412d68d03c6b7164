// An executable pass graph (Filament's FrameGraph, Falcor's render graph): each pass declares in its setup the
// typed resources it creates, reads and writes, and does its work in its execute. compile() culls from the
// requested outputs (output files and requested resources): a pass nobody reads never runs; it orders the passes
// topologically (declaration order among independent passes) and computes each resource's lifetime; execute()
// creates a resource with a descriptor just before its first use, and frees every resource after its last use.
// A read of a resource no pass writes (and nobody imported), two writers of one resource, or a cycle is a
// GraphError naming the passes and the resource. No GL here: GL resources are types with a Descriptor and a
// static create(), like any other.
#pragma once

#include <any>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace metalfit::glpreview::graph {

class GraphError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

enum class Processor { cpu, gpu };

// A typed reference to a resource of one graph.
template <typename T>
struct Handle {
    std::size_t index = static_cast<std::size_t>(-1);
};

// The data of a pass with a single output.
template <typename T>
struct Out {
    Handle<T> out;
};

// The sink of an output file: its writer pass is bound to it by declaring it (Builder::write_file).
struct OutputFile {
    std::string name;  // "beauty.exr"
};

// Types the graph creates itself from a descriptor: `typename T::Descriptor` and `static T T::create(const
// Descriptor&)` (a cube map of a size and format, a 1D LUT texture, a colour target ...).
template <typename T>
concept Creatable = requires(const typename T::Descriptor& d) {
    {T::create(d)};
};

struct PassInfo {
    std::string name;
    std::string why;  // for --explain
    Processor processor = Processor::cpu;
};

class PassGraph;

// What a pass may declare in its setup.
class Builder {
public:
    // A resource the graph creates from `descriptor` just before this pass runs (this pass writes it).
    template <Creatable T>
    Handle<T> create(std::string name, typename T::Descriptor descriptor);
    // A resource this pass produces in its execute (Resources::emplace).
    template <typename T>
    Handle<T> produce(std::string name);
    // The output file this pass writes: a sink, requested by construction.
    Handle<OutputFile> write_file(std::string file);
    template <typename T>
    Handle<T> read(Handle<T> resource);
    template <typename T>
    Handle<T> write(Handle<T> resource);

private:
    friend class PassGraph;
    Builder(PassGraph& graph, std::size_t pass) : graph_(graph), pass_(pass) {}
    PassGraph& graph_;
    std::size_t pass_;
};

// What a pass may touch in its execute: only the resources it declared.
class Resources {
public:
    template <typename T>
    T& get(Handle<T> resource);
    template <typename T, typename... Args>
    T& emplace(Handle<T> resource, Args&&... args);

private:
    friend class PassGraph;
    Resources(PassGraph& graph, std::size_t pass) : graph_(graph), pass_(pass) {}
    std::any& slot(std::size_t resource);
    PassGraph& graph_;
    std::size_t pass_;
};

// A compiled graph as --explain shows it.
struct CompiledPass {
    std::string name, why;
    Processor processor = Processor::cpu;
    std::vector<std::string> reads, writes;
};
struct SkippedPass {
    std::string name, why;
};
struct Lifetime {
    std::string resource;
    std::size_t first = 0, last = 0;  // positions in the execution order
};

class PassGraph {
public:
    PassGraph() = default;
    PassGraph(const PassGraph&) = delete;
    PassGraph& operator=(const PassGraph&) = delete;

    // A pass: setup(Builder&, Data&) declares, execute(const Data&, Resources&) works. Returns the pass's data (its
    // handles), valid as long as the graph, for the passes that read them.
    template <typename Data, typename Setup, typename Execute>
    const Data& add_pass(PassInfo info, Setup&& setup, Execute&& execute);

    // A resource from outside the graph (the scene's camera, its materials ...): never created, never freed here.
    template <typename T>
    Handle<T> import(std::string name, T value = T{});
    // A resource with no writer yet; a pass's Builder::write() makes it its writer.
    template <typename T>
    Handle<T> declare(std::string name);
    // Keeps a resource alive after the graph ran (for the caller) and makes it a requested output.
    template <typename T>
    void request(Handle<T> resource);
    // Keeps a resource alive after the graph ran, without asking for it (it stays empty when its writer is culled).
    template <typename T>
    void retain(Handle<T> resource);
    // A pass that is not even a candidate, and why (--explain).
    void skip(std::string name, std::string why) { skipped_.push_back({std::move(name), std::move(why)}); }

    // Called once, before the first GPU pass runs and before its resources are created (opens the GL context).
    void before_first_gpu_pass(std::function<void()> open) { open_gpu_ = std::move(open); }

    // Culls, orders, computes lifetimes. Throws GraphError. Call once, before execute().
    void compile();
    // Runs the kept passes in order.
    void execute();

    bool runs(const std::string& pass) const;
    const std::vector<CompiledPass>& passes() const { return compiled_; }  // kept, in execution order
    const std::vector<SkippedPass>& skipped() const { return skipped_; }   // not planned, then culled
    const std::vector<Lifetime>& lifetimes() const { return lifetimes_; }
    std::vector<std::string> output_files() const;  // sinks, in declaration order

    // A retained or requested resource after execute() (nullptr when its writer was culled).
    template <typename T>
    T* result(Handle<T> resource);

private:
    friend class Builder;
    friend class Resources;

    struct Resource {
        std::string name;
        bool imported = false, sink = false, requested = false, retained = false;
        std::optional<std::size_t> writer;
        std::function<std::any()> create;  // empty: the writer emplaces it
        std::any value;
    };
    struct Pass {
        PassInfo info;
        std::vector<std::size_t> reads, writes;
        std::function<void(Resources&)> execute;
    };

    std::size_t add_resource(std::string name);
    void declare_read(std::size_t pass, std::size_t resource);
    void declare_write(std::size_t pass, std::size_t resource);
    bool declared(std::size_t pass, std::size_t resource) const;
    std::vector<std::string> names(const std::vector<std::size_t>& resources) const;

    std::vector<Resource> resources_;
    std::vector<Pass> passes_;
    std::vector<std::shared_ptr<void>> pass_data_;
    std::vector<SkippedPass> skipped_;
    std::vector<std::size_t> order_;  // kept passes, in execution order
    std::vector<CompiledPass> compiled_;
    std::vector<Lifetime> lifetimes_;
    std::vector<std::size_t> lifetime_of_;  // the resource of lifetimes_[i]
    bool compiled_flag_ = false;
    std::function<void()> open_gpu_;
};

// ---- templates ----

template <Creatable T>
Handle<T> Builder::create(std::string name, typename T::Descriptor descriptor) {
    const std::size_t r = graph_.add_resource(std::move(name));
    graph_.resources_[r].create = [descriptor] { return std::any(std::make_shared<T>(T::create(descriptor))); };
    graph_.declare_write(pass_, r);
    return {r};
}

template <typename T>
Handle<T> Builder::produce(std::string name) {
    const std::size_t r = graph_.add_resource(std::move(name));
    graph_.declare_write(pass_, r);
    return {r};
}

inline Handle<OutputFile> Builder::write_file(std::string file) {
    const std::size_t r = graph_.add_resource("file:" + file);
    graph_.resources_[r].sink = true;
    graph_.resources_[r].create = [file] { return std::any(std::make_shared<OutputFile>(OutputFile{file})); };
    graph_.declare_write(pass_, r);
    return {r};
}

template <typename T>
Handle<T> Builder::read(Handle<T> resource) {
    graph_.declare_read(pass_, resource.index);
    return resource;
}

template <typename T>
Handle<T> Builder::write(Handle<T> resource) {
    graph_.declare_write(pass_, resource.index);
    return resource;
}

template <typename T>
T& Resources::get(Handle<T> resource) {
    std::any& value = slot(resource.index);
    if (!value.has_value())
        throw GraphError("resource '" + graph_.resources_.at(resource.index).name + "' is read before it is written");
    auto* pointer = std::any_cast<std::shared_ptr<T>>(&value);
    if (!pointer) throw GraphError("resource '" + graph_.resources_.at(resource.index).name + "' has another type");
    return **pointer;
}

template <typename T, typename... Args>
T& Resources::emplace(Handle<T> resource, Args&&... args) {
    std::any& value = slot(resource.index);
    auto made = std::make_shared<T>(std::forward<Args>(args)...);
    value = made;
    return *made;
}

template <typename Data, typename Setup, typename Execute>
const Data& PassGraph::add_pass(PassInfo info, Setup&& setup, Execute&& execute) {
    if (compiled_flag_) throw GraphError("pass '" + info.name + "' added after compile()");
    auto data = std::make_shared<Data>();
    const std::size_t index = passes_.size();
    passes_.push_back({std::move(info), {}, {}, {}});
    pass_data_.push_back(data);
    Builder builder(*this, index);
    setup(builder, *data);
    passes_[index].execute = [data, run = std::forward<Execute>(execute)](Resources& resources) {
        run(*data, resources);
    };
    return *data;
}

template <typename T>
Handle<T> PassGraph::import(std::string name, T value) {
    const std::size_t r = add_resource(std::move(name));
    resources_[r].imported = true;
    resources_[r].value = std::make_shared<T>(std::move(value));
    return {r};
}

template <typename T>
Handle<T> PassGraph::declare(std::string name) {
    return {add_resource(std::move(name))};
}

template <typename T>
void PassGraph::request(Handle<T> resource) {
    resources_.at(resource.index).requested = true;
    resources_.at(resource.index).retained = true;
}

template <typename T>
void PassGraph::retain(Handle<T> resource) {
    resources_.at(resource.index).retained = true;
}

template <typename T>
T* PassGraph::result(Handle<T> resource) {
    std::any& value = resources_.at(resource.index).value;
    auto* pointer = std::any_cast<std::shared_ptr<T>>(&value);
    return pointer && *pointer ? pointer->get() : nullptr;
}

}  // namespace metalfit::glpreview::graph
