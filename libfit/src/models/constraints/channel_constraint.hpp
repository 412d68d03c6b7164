// A constraint of one channel's solve (internal: fit_channel.hpp composes the active ones, ConstraintSet): what it
// does to the Ceres problem of a model — the residual block of the curve it replaces, residual blocks of its own,
// the bounds of a parameter, the parameter it holds — whether the plain fit's shortcuts (the variable projection,
// the start pruning) still apply under it, how a start is moved into it, what it does after a solve (drive the
// solution into it and say whether it holds) and how a solution's parameters are read back. docs/fitting.md,
// "Targets and constraints".
#pragma once

#include <ceres/ceres.h>

#include <array>
#include <optional>

#include "libfit/models/model.hpp"

namespace metalfit::detail {

// Not a template: what a constraint does is said in terms every model shares (the problem, the parameter block);
// only the kinds that need the model's type (their residual functors) are templates over it.
class ChannelConstraint {
public:
    virtual ~ChannelConstraint() = default;

    // The curve's residual block under the constraint (the problem takes ownership), or nullptr: the plain curve's.
    // At most one active constraint replaces it (FitConstraints::check_combination).
    virtual ceres::CostFunction* curve_residual(const ChannelTarget& /*target*/) const { return nullptr; }
    // Residual blocks of its own over the parameter block x, added before the curve's. One problem at a time: a
    // constraint may keep per-solve state (the gamut's penalty weight) from here to after_solve.
    virtual void add_residuals(ceres::Problem& /*problem*/, double* /*x*/) const {}
    // The bounds of parameter i in the solve, where the constraint sets them (else the model's).
    virtual std::optional<std::array<double, 2>> bounds(int /*i*/) const { return std::nullopt; }
    // The parameter the solver holds constant (its value is computed inside the residual), or −1.
    virtual int held_parameter() const { return -1; }
    // Whether the plain fit's variable projection (which solves the linear parameters freely) and start pruning
    // (a rule measured on plain fits) still apply.
    virtual bool keeps_projection() const = 0;
    virtual bool keeps_start_pruning() const = 0;
    // A start (clamped into the model's bounds) moved into the constraint's coordinates.
    virtual void prepare_start(ChannelParameters& /*x*/) const {}
    // After a solve of `problem` from x: whatever the constraint does to drive the solution into it (more solves
    // with `options`); false where this start cannot hold it (the start is dropped).
    virtual bool after_solve(ceres::Problem& /*problem*/, const ceres::Solver::Options& /*options*/,
                             ChannelParameters& /*x*/, ceres::Solver::Summary& /*summary*/) const {
        return true;
    }
    // The solution's parameters as the model evaluates them (the held parameter computed from the others).
    virtual void finish(ChannelParameters& /*x*/) const {}
};

}  // namespace metalfit::detail
