#include "libfit/reference/reference_curve.hpp"

#include <algorithm>
#include <sstream>

#include "libfit/base/errors.hpp"
#include "libfit/io/layer_stack.hpp"
#include "libfit/optics/fresnel_real.hpp"
#include "libfit/reference/stack_grid.hpp"

namespace metalfit {
namespace {

void require_visible_coverage(const Material& m, const SpectralOptions& options) {
    if (options.out_of_range == OutOfRange::clamp) return;
    for (const auto& [curve, what] : {std::pair{&m.index.n, "n"}, std::pair{&m.index.k, "k"}}) {
        const WavelengthRange r = curve->range();
        if (r.covers(kVisibleRange)) continue;
        std::ostringstream s;
        s << what << " covers " << r.min_nm << "–" << r.max_nm << " nm, but colour needs " << kVisibleRange.min_nm
          << "–" << kVisibleRange.max_nm << " nm (--extrapolate holds the end values outside the measured range)";
        throw InputError({m.provenance.file, 0, "DATA"}, s.str());
    }
}

std::string nm(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

std::vector<std::string> held_constant_ranges(const Material& m, const WavelengthRange& needed,
                                              const SpectralOptions& options) {
    std::vector<std::string> notes;
    if (options.out_of_range != OutOfRange::clamp) return notes;
    for (const auto& [curve, what] : {std::pair{&m.index.n, "n"}, std::pair{&m.index.k, "k"}}) {
        const WavelengthRange r = curve->range();
        const std::string measured = " (--extrapolate; measured " + nm(r.min_nm) + "–" + nm(r.max_nm) + " nm)";
        if (r.min_nm > needed.min_nm)
            notes.push_back(std::string(what) + " held at its " + nm(r.min_nm) + " nm value over " + nm(needed.min_nm) +
                            "–" + nm(std::min(r.min_nm, needed.max_nm)) + " nm" + measured);
        if (r.max_nm < needed.max_nm)
            notes.push_back(std::string(what) + " held at its " + nm(r.max_nm) + " nm value over " +
                            nm(std::max(r.max_nm, needed.min_nm)) + "–" + nm(needed.max_nm) + " nm" + measured);
    }
    return notes;
}

ReferenceCurve::ReferenceCurve(const Material& material, const Colorimetry& colorimetry, ColorSpaceConverter converter,
                               SpectralOptions options)
    : colorimetry_(colorimetry), converter_(std::move(converter)) {
    require_visible_coverage(material, options);
    const DenseSpectrum<XYZ>& grid = colorimetry_.weights();
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const SquaredIndex<double> e =
            squared_index(material.index(grid.nm(i), options.interpolation, options.out_of_range));
        eta2_re_.push_back(e.re);
        eta2_re_minus_1_.push_back(e.re_minus_1);
        eta2_im_.push_back(e.im);
        eta2_norm2_.push_back(e.norm2);
        weight_x_.push_back(grid[i].X);
        weight_y_.push_back(grid[i].Y);
        weight_z_.push_back(grid[i].Z);
    }
    raw_white_ = converter_(colorimetry_.white());
    const WavelengthRange needed{double(grid.first_nm()), double(grid.last_nm())};
    held_constant_ = held_constant_ranges(material, needed, options);
    if (material.layers && !material.layers->empty()) {
        require_layer_coverage(*material.layers, kVisibleRange, options);
        stack_ = stack_optics_on_grid(material, grid.first_nm(), grid.last_nm(), options);
        for (std::string& note : layer_held_constant(*material.layers, needed, options))
            held_constant_.push_back(std::move(note));
    }
}

namespace {

// μ values evaluated together: the inner loop over them is what the compiler vectorises (2 lanes with SSE2, 4 with
// AVX2), with the per-λ constants broadcast.
constexpr std::size_t kLanes = 8;

// The columns of the per-λ constants and weights.
struct SpectralColumns {
    const double *re, *re1, *im, *norm2, *wx, *wy, *wz;
    std::size_t size;
};

// Σ_λ F(μ_j, λ) w(λ) for kLanes values of μ. On x86-64 GCC also builds an AVX2 clone, chosen at load time (ifunc);
// both clones use the same IEEE operations (no FMA), so the values do not depend on the machine. The sums are kept
// in local arrays (the compiler cannot keep sums behind pointers in registers: they might alias the columns) and μ is
// clamped once, so that the loop over the lanes compiles to vector operations without branches.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("avx2", "default")))
#endif
void integrate_lanes(const SpectralColumns& s, const double* mu, double* x_out, double* y_out, double* z_out) {
    double m[kLanes], x[kLanes] = {}, y[kLanes] = {}, z[kLanes] = {};
    for (std::size_t j = 0; j < kLanes; ++j)
        m[j] = fresnel_real_detail::min_of(fresnel_real_detail::max_of(mu[j], 0.0), 1.0);
    for (std::size_t i = 0; i < s.size; ++i) {
        const double re = s.re[i], re1 = s.re1[i], im = s.im[i], norm2 = s.norm2[i];
        const double wx = s.wx[i], wy = s.wy[i], wz = s.wz[i];
        for (std::size_t j = 0; j < kLanes; ++j) {
            const double f = fresnel_real(m[j], re, re1, im, norm2);
            x[j] += f * wx;  // Σ_λ F(λ) w(λ) in grid order, as sum_of_products
            y[j] += f * wy;
            z[j] += f * wz;
        }
    }
    for (std::size_t j = 0; j < kLanes; ++j) x_out[j] = x[j], y_out[j] = y[j], z_out[j] = z[j];
}

}  // namespace

std::vector<XYZ> ReferenceCurve::xyz(std::span<const double> mu) const {
    std::vector<XYZ> out(mu.size());
    if (!stack_.empty()) {  // a layered material: Σ_λ R_stack(λ, μ) w(λ) in grid order
        for (std::size_t j = 0; j < mu.size(); ++j) {
            double x = 0, y = 0, z = 0;
            for (std::size_t i = 0; i < stack_.size(); ++i) {
                const double f = stack_reflectance_unpolarized(mu[j], stack_[i]);
                x += f * weight_x_[i];
                y += f * weight_y_[i];
                z += f * weight_z_[i];
            }
            out[j] = XYZ{x, y, z};
        }
        return out;
    }
    const SpectralColumns columns{eta2_re_.data(),  eta2_re_minus_1_.data(), eta2_im_.data(),  eta2_norm2_.data(),
                                  weight_x_.data(), weight_y_.data(),        weight_z_.data(), eta2_re_.size()};
    for (std::size_t first = 0; first < mu.size(); first += kLanes) {
        const std::size_t count = std::min(kLanes, mu.size() - first);
        double m[kLanes], x[kLanes], y[kLanes], z[kLanes];
        for (std::size_t j = 0; j < kLanes; ++j) m[j] = mu[first + std::min(j, count - 1)];  // padded with the last μ
        integrate_lanes(columns, m, x, y, z);
        for (std::size_t j = 0; j < count; ++j) out[first + j] = XYZ{x[j], y[j], z[j]};
    }
    return out;
}

XYZ ReferenceCurve::xyz(double mu) const { return xyz(std::span<const double>(&mu, 1)).front(); }

std::vector<RGB> ReferenceCurve::operator()(std::span<const double> mu) const {
    std::vector<RGB> out;
    out.reserve(mu.size());
    for (const XYZ& v : xyz(mu)) out.push_back(converter_(v) / raw_white_);
    return out;
}

RGB ReferenceCurve::operator()(double mu) const { return converter_(xyz(mu)) / raw_white_; }

}  // namespace metalfit
