// The active constraints of one channel's solve, composed (internal): built from ChannelConstraints (which
// FitConstraints::check_combination has passed), asked by fit_channel instead of a branch per constraint.
#pragma once

#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "libfit/models/registry.hpp"
#include "models/constraints/channel_constraint.hpp"
#include "models/constraints/f0_range.hpp"
#include "models/constraints/pinned_f0.hpp"
#include "models/constraints/unit_range.hpp"

namespace metalfit::detail {

// Not a template (the model enters through its parameters' bounds and the kinds made for it by constraint_set<M>),
// so that its code is compiled once, not once per model.
class ConstraintSet {
public:
    ConstraintSet(std::vector<std::unique_ptr<const ChannelConstraint>> active, std::span<const Parameter> parameters)
        : active_(std::move(active)), parameters_(parameters) {}

    // No constraint at all: the plain fit.
    bool empty() const { return active_.empty(); }
    // The curve's residual block of the constraint that replaces it, else nullptr (the plain curve's).
    ceres::CostFunction* curve_residual(const ChannelTarget& target) const {
        for (const auto& c : active_)
            if (ceres::CostFunction* f = c->curve_residual(target)) return f;
        return nullptr;
    }
    void add_residuals(ceres::Problem& problem, double* x) const {
        for (const auto& c : active_) c->add_residuals(problem, x);
    }
    double lower(int i) const {
        for (const auto& c : active_)
            if (const auto b = c->bounds(i)) return (*b)[0];
        return parameters_[static_cast<std::size_t>(i)].lower;
    }
    double upper(int i) const {
        for (const auto& c : active_)
            if (const auto b = c->bounds(i)) return (*b)[1];
        return parameters_[static_cast<std::size_t>(i)].upper;
    }
    int held_parameter() const {
        for (const auto& c : active_)
            if (const int i = c->held_parameter(); i >= 0) return i;
        return -1;
    }
    bool keeps_projection() const {
        for (const auto& c : active_)
            if (!c->keeps_projection()) return false;
        return true;
    }
    bool keeps_start_pruning() const {
        for (const auto& c : active_)
            if (!c->keeps_start_pruning()) return false;
        return true;
    }
    void prepare_start(ChannelParameters& x) const {
        for (const auto& c : active_) c->prepare_start(x);
    }
    bool after_solve(ceres::Problem& problem, const ceres::Solver::Options& options, ChannelParameters& x,
                     ceres::Solver::Summary& summary) const {
        for (const auto& c : active_)
            if (!c->after_solve(problem, options, x, summary)) return false;
        return true;
    }
    void finish(ChannelParameters& x) const {
        for (const auto& c : active_) c->finish(x);
    }

private:
    std::vector<std::unique_ptr<const ChannelConstraint>> active_;
    std::span<const Parameter> parameters_;
};

// The active constraints of `constraints` for the model M.
template <class M>
ConstraintSet constraint_set(const ChannelConstraints& constraints) {
    std::vector<std::unique_ptr<const ChannelConstraint>> active;
    if (constraints.unit_range) active.push_back(std::make_unique<UnitRange<M>>());
    if constexpr (PinnableF0<M>) {
        if (constraints.pinned_f0) active.push_back(std::make_unique<PinnedF0<M>>(*constraints.pinned_f0));
        if (constraints.f0_range) active.push_back(std::make_unique<F0Range<M>>(*constraints.f0_range));
    } else {
        if (constraints.pinned_f0) throw std::logic_error(std::string(M::kId) + " cannot pin F0");
        if (constraints.f0_range) throw std::logic_error(std::string(M::kId) + " cannot bound F0");
    }
    return ConstraintSet(std::move(active), M::kParameters);
}

}  // namespace metalfit::detail
