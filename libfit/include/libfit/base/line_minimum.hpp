// The local minimum of a smooth function of one bounded, positive parameter, from a start, with the function's
// derivative: what the variable-projection fits solve when one non-linear parameter is left (lazanyi-comp's α).
// Downhill from the start in steps growing geometrically (halved where the function rose: the start's valley) until
// the derivative changes sign or a bound is reached, then Brent's root search (zeroin: bisection safeguarding secant
// and inverse quadratic steps) on the derivative inside that bracket.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace metalfit {

struct LinePoint {
    double x = 0, value = 0, slope = 0;  // the function and its derivative at x
};

struct LineMinimum {
    LinePoint start;         // at the start, clamped into the bounds
    LinePoint minimum;       // where the search ended
    int evaluations = 0;     // after the start's
    bool converged = false;  // false: the evaluation limit was reached first
    int same_as = -1;  // ≥ 0: the bracket holds known[same_as], not refined (minimum: the lower end of the bracket)
};

// f(x) → LinePoint for x ∈ [lower, upper], 0 < lower < upper. `known`: minima found before (from other starts); a
// bracket that holds one of them is not refined (the same valley, the same minimum: same_as says which). The steps
// are taken in ln x (the scale of an exponent): the first kFirstStep, then where the secant of the derivative
// predicts its zero (a little beyond), between half the last step (at least kShortestStep) and kGrowth times it. The
// search ends where the bracket is narrower than kRelativeTolerance · x (plus Brent's 4 ε |x|), where the derivative
// is exactly 0, or on a bound the derivative points out of.
struct LineSearchSettings {
    static constexpr double kFirstStep = 0.1;
    static constexpr double kGrowth = 4.0;
    static constexpr double kShortestStep = 0.01;
    static constexpr double kRelativeTolerance = 1e-12;
    static constexpr int kMaxEvaluations = 100;
};

template <class F>
LineMinimum line_minimum(F&& f, double x0, double lower, double upper, std::span<const double> known = {}) {
    using S = LineSearchSettings;
    LineMinimum result;
    const auto evaluate = [&](double x) {
        ++result.evaluations;
        return f(x);
    };
    // The search's end: where, and whether it converged there (else the evaluation limit or a non-finite slope).
    const auto end_at = [&result](const LinePoint& at, bool converged) {
        result.minimum = at;
        result.converged = converged;
        return result;
    };
    LinePoint p = f(std::clamp(x0, lower, upper));
    result.start = p;
    if (!std::isfinite(p.slope) || p.slope == 0) return end_at(p, std::isfinite(p.slope));
    // Bracketing: walk downhill until the slope changes sign.
    const double direction = p.slope < 0 ? 1.0 : -1.0;
    const double bound = direction > 0 ? upper : lower;
    double step = S::kFirstStep;
    LinePoint previous = p;
    LinePoint next = p;
    for (;;) {
        // The minimum on the bound: the slope points out of the interval.
        if (previous.x == bound) return end_at(previous, true);
        if (result.evaluations >= S::kMaxEvaluations) return end_at(previous, false);
        const double t = std::log(previous.x) + direction * step;
        const double x = direction > 0 ? std::min(std::exp(t), upper) : std::max(std::exp(t), lower);
        next = evaluate(x);
        if (!std::isfinite(next.slope)) return end_at(previous, false);  // stop short of what cannot be evaluated
        if (next.slope * direction >= 0) break;  // a sign change (or 0): a minimum in [previous, next]
        if (next.value > previous.value) {  // higher, the slope pointing on: a ridge stepped over; stay in this valley
            step = 0.5 * std::abs(std::log(next.x) - std::log(previous.x));
            continue;
        }
        // The secant of the slope in ln x: where it predicts 0, a little beyond, within [step / 2, kGrowth step]
        // (and no shorter than kShortestStep).
        const double last = std::abs(std::log(next.x) - std::log(previous.x));
        const double ahead = next.slope * last / (previous.slope - next.slope);  // > 0 where |slope| decreases
        step = ahead > 0 ? std::clamp(1.25 * ahead, std::max(0.5 * last, S::kShortestStep), S::kGrowth * last)
                         : S::kGrowth * last;
        previous = next;
    }
    if (next.slope == 0) return end_at(next, true);
    for (std::size_t k = 0; k < known.size(); ++k)
        if (known[k] >= std::min(previous.x, next.x) && known[k] <= std::max(previous.x, next.x)) {
            result.same_as = static_cast<int>(k);
            return end_at(previous.value <= next.value ? previous : next, true);
        }
    // Brent's zeroin on the slope in [previous, next] (R. P. Brent, "Algorithms for Minimization without Derivatives",
    // 1973, chapter 4), b the best point so far.
    LinePoint a = previous, b = next, c = a;
    double d = b.x - a.x, e = d;
    constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
    for (;;) {
        if ((b.slope > 0) == (c.slope > 0)) {
            c = a;
            d = e = b.x - a.x;
        }
        if (std::abs(c.slope) < std::abs(b.slope)) {
            a = b;
            b = c;
            c = a;
        }
        const double tolerance = 2 * kEpsilon * std::abs(b.x) + 0.5 * S::kRelativeTolerance * std::abs(b.x);
        const double half = 0.5 * (c.x - b.x);
        if (std::abs(half) <= tolerance || b.slope == 0) return end_at(b, true);
        if (result.evaluations >= S::kMaxEvaluations) return end_at(b, false);
        if (std::abs(e) >= tolerance && std::abs(a.slope) > std::abs(b.slope)) {
            const double s = b.slope / a.slope;
            double p, q;
            if (a.x == c.x) {  // secant
                p = 2 * half * s;
                q = 1 - s;
            } else {  // inverse quadratic interpolation
                const double qa = a.slope / c.slope, r = b.slope / c.slope;
                p = s * (2 * half * qa * (qa - r) - (b.x - a.x) * (r - 1));
                q = (qa - 1) * (r - 1) * (s - 1);
            }
            if (p > 0)
                q = -q;
            else
                p = -p;
            if (2 * p < std::min(3 * half * q - std::abs(tolerance * q), std::abs(e * q))) {
                e = d;
                d = p / q;
            } else {
                d = half;
                e = d;
            }
        } else {
            d = half;
            e = d;
        }
        a = b;
        const double x = b.x + (std::abs(d) > tolerance ? d : std::copysign(tolerance, half));
        b = evaluate(std::clamp(x, lower, upper));
        if (!std::isfinite(b.slope)) return end_at(a, false);
    }
}

}  // namespace metalfit
