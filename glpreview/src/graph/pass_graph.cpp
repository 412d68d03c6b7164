#include "glpreview/graph/pass_graph.hpp"

#include <algorithm>
#include <set>

#include "libfit/base/text.hpp"

namespace metalfit::glpreview::graph {
std::any& Resources::slot(std::size_t resource) {
    if (!graph_.declared(pass_, resource))
        throw GraphError("pass '" + graph_.passes_.at(pass_).info.name + "' uses '" +
                         graph_.resources_.at(resource).name + "' without declaring it in its setup");
    return graph_.resources_[resource].value;
}

std::size_t PassGraph::add_resource(std::string name) {
    resources_.push_back({std::move(name), false, false, false, false, std::nullopt, {}, {}});
    return resources_.size() - 1;
}

void PassGraph::declare_read(std::size_t pass, std::size_t resource) {
    if (resource >= resources_.size())
        throw GraphError("pass '" + passes_.at(pass).info.name + "' reads an unknown resource");
    passes_.at(pass).reads.push_back(resource);
}

void PassGraph::declare_write(std::size_t pass, std::size_t resource) {
    Resource& r = resources_.at(resource);
    if (r.imported)
        throw GraphError("pass '" + passes_.at(pass).info.name + "' writes the imported resource '" + r.name + "'");
    if (r.writer && *r.writer != pass)
        throw GraphError("resource '" + r.name + "' is written by two passes: '" + passes_.at(*r.writer).info.name +
                         "' and '" + passes_.at(pass).info.name + "'");
    r.writer = pass;
    passes_.at(pass).writes.push_back(resource);
}

bool PassGraph::declared(std::size_t pass, std::size_t resource) const {
    const Pass& p = passes_.at(pass);
    return std::count(p.reads.begin(), p.reads.end(), resource) +
               std::count(p.writes.begin(), p.writes.end(), resource) >
           0;
}

std::vector<std::string> PassGraph::names(const std::vector<std::size_t>& resources) const {
    std::vector<std::string> result;
    for (std::size_t r : resources) result.push_back(resources_[r].name);
    return result;
}

void PassGraph::compile() {
    if (compiled_flag_) throw GraphError("compile() called twice");
    compiled_flag_ = true;
    for (const Pass& p : passes_)
        for (std::size_t r : p.reads)
            if (!resources_[r].imported && !resources_[r].writer)
                throw GraphError("pass '" + p.info.name + "' reads '" + resources_[r].name +
                                 "', which no pass writes and nobody imported");

    // Cull: walk back from the sinks and the requested resources.
    std::vector<bool> needed(resources_.size(), false), keep(passes_.size(), false);
    std::vector<std::size_t> work;
    for (std::size_t r = 0; r < resources_.size(); ++r)
        if (resources_[r].sink || resources_[r].requested) {
            needed[r] = true;
            work.push_back(r);
        }
    while (!work.empty()) {
        const std::size_t r = work.back();
        work.pop_back();
        if (!resources_[r].writer || keep[*resources_[r].writer]) continue;
        const std::size_t w = *resources_[r].writer;
        keep[w] = true;
        for (std::size_t read : passes_[w].reads)
            if (!needed[read]) {
                needed[read] = true;
                work.push_back(read);
            }
    }

    // Order the kept passes: Kahn's algorithm, the earliest declared ready pass first (so a graph declared in a
    // valid order runs in that order).
    std::vector<std::size_t> missing(passes_.size(), 0);
    for (std::size_t p = 0; p < passes_.size(); ++p)
        if (keep[p])
            for (std::size_t r : passes_[p].reads)
                if (resources_[r].writer && *resources_[r].writer != p) ++missing[p];
    std::set<std::size_t> ready;
    for (std::size_t p = 0; p < passes_.size(); ++p)
        if (keep[p] && missing[p] == 0) ready.insert(p);
    while (!ready.empty()) {
        const std::size_t p = *ready.begin();
        ready.erase(ready.begin());
        order_.push_back(p);
        for (std::size_t q = 0; q < passes_.size(); ++q) {
            if (!keep[q] || q == p) continue;
            for (std::size_t r : passes_[q].reads)
                if (resources_[r].writer == p && --missing[q] == 0) ready.insert(q);
        }
    }
    std::size_t kept = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), true));
    if (order_.size() != kept) {
        std::vector<std::string> cycle;
        for (std::size_t p = 0; p < passes_.size(); ++p)
            if (keep[p] && std::find(order_.begin(), order_.end(), p) == order_.end())
                cycle.push_back(passes_[p].info.name);
        throw GraphError("the passes " + join(cycle) + " depend on each other in a cycle");
    }

    // Explain and lifetimes.
    for (std::size_t p : order_)
        compiled_.push_back({passes_[p].info.name, passes_[p].info.why, passes_[p].info.processor,
                             names(passes_[p].reads), names(passes_[p].writes)});
    for (std::size_t p = 0; p < passes_.size(); ++p)
        if (!keep[p])
            skipped_.push_back(
                {passes_[p].info.name, "culled: nothing asked for reads " + join(names(passes_[p].writes))});
    for (std::size_t r = 0; r < resources_.size(); ++r) {
        std::optional<std::size_t> first, last;
        for (std::size_t i = 0; i < order_.size(); ++i)
            if (declared(order_[i], r)) {
                if (!first) first = i;
                last = i;
            }
        if (first) {
            lifetimes_.push_back({resources_[r].name, *first, *last});
            lifetime_of_.push_back(r);
        }
    }
}

void PassGraph::execute() {
    if (!compiled_flag_) throw GraphError("execute() before compile()");
    std::vector<const Lifetime*> by_resource(resources_.size(), nullptr);
    for (std::size_t l = 0; l < lifetimes_.size(); ++l) by_resource[lifetime_of_[l]] = &lifetimes_[l];
    for (std::size_t i = 0; i < order_.size(); ++i) {
        if (passes_[order_[i]].info.processor == Processor::gpu && open_gpu_) std::exchange(open_gpu_, nullptr)();
        for (std::size_t r = 0; r < resources_.size(); ++r)
            if (by_resource[r] && by_resource[r]->first == i && resources_[r].create)
                resources_[r].value = resources_[r].create();
        Resources resources(*this, order_[i]);
        passes_[order_[i]].execute(resources);
        for (std::size_t r = 0; r < resources_.size(); ++r)
            if (by_resource[r] && by_resource[r]->last == i && !resources_[r].imported && !resources_[r].retained)
                resources_[r].value.reset();
    }
}

bool PassGraph::runs(const std::string& pass) const {
    return std::any_of(compiled_.begin(), compiled_.end(), [&](const CompiledPass& p) { return p.name == pass; });
}

std::vector<std::string> PassGraph::output_files() const {
    std::vector<std::string> files;
    for (const Resource& r : resources_)
        if (r.sink) files.push_back(r.name.substr(5));
    return files;
}

}  // namespace metalfit::glpreview::graph
