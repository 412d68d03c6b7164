#include "libfit/reference/stack_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "libfit/base/errors.hpp"

namespace metalfit {
namespace {

std::string nm(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// The layer's material in messages: its file, or "n = 1.5" for a constant.
std::filesystem::path where(const LayerMaterial& m) {
    return m.provenance.file.empty() ? std::filesystem::path(m.name) : m.provenance.file;
}

void require_covers(const LayerMaterial& m, const char* layer, const WavelengthRange& needed) {
    for (const auto& [curve, what] : {std::pair{&m.index.n, "n"}, std::pair{&m.index.k, "k"}}) {
        const WavelengthRange r = curve->range();
        if (r.covers(needed)) continue;
        std::string missing;
        if (r.min_nm > needed.min_nm) missing = nm(needed.min_nm) + "–" + nm(std::min(r.min_nm, needed.max_nm)) + " nm";
        if (r.max_nm < needed.max_nm)
            missing += (missing.empty() ? "" : " and ") + nm(std::max(r.max_nm, needed.min_nm)) + "–" +
                       nm(needed.max_nm) + " nm";
        throw InputError({where(m), 0, "DATA"},
                         std::string(layer) + " " + what + " covers " + nm(r.min_nm) + "–" + nm(r.max_nm) +
                             " nm, but colour needs " + nm(needed.min_nm) + "–" + nm(needed.max_nm) + " nm: " +
                             missing + " missing (--extrapolate holds the end values outside the measured range)");
    }
}

// A coat's index on the grid must be at least 1 (a dielectric at least as dense as air).
void require_coat_index(const ClearCoat& coat, int lambda, double n) {
    if (!(n >= 1.0))
        throw InputError({where(coat.material), 0, "DATA"},
                         "coat n = " + nm(n) + " at " + nm(lambda) +
                             " nm is below 1: a coat is a dielectric at least as dense as air");
}

std::string layer_label(const char* layer, const LayerMaterial& m) {
    return std::string(layer) + " " + m.id + (m.source.empty() || m.source == m.id ? "" : " (" + m.source + ")");
}

}  // namespace

void require_layer_coverage(const LayerStack& layers, const WavelengthRange& needed, const SpectralOptions& options) {
    if (options.out_of_range != OutOfRange::clamp) {
        if (layers.film) require_covers(layers.film->material, "film", needed);
        if (layers.coat) require_covers(layers.coat->material, "coat", needed);
    }
    if (layers.coat)
        for (int lambda = int(std::ceil(needed.min_nm)); lambda <= int(std::floor(needed.max_nm)); ++lambda)
            require_coat_index(*layers.coat, lambda,
                               layers.coat->material.index.n(lambda, options.interpolation, options.out_of_range));
}

std::vector<StackOptics<double>> stack_optics_on_grid(const Material& metal, int first_nm, int last_nm,
                                                      const SpectralOptions& options) {
    const LayerStack& layers = *metal.layers;
    std::vector<StackOptics<double>> grid;
    grid.reserve(static_cast<std::size_t>(last_nm - first_nm + 1));
    for (int lambda = first_nm; lambda <= last_nm; ++lambda) {
        StackOptics<double> o;
        o.metal = metal.index(lambda, options.interpolation, options.out_of_range);
        if (layers.film) {
            o.has_film = true;
            o.film = layers.film->material.index(lambda, options.interpolation, options.out_of_range);
            o.film_thickness_per_wavelength = layers.film->thickness_nm / lambda;
        }
        if (layers.coat) {
            const ClearCoat& coat = *layers.coat;
            const std::complex<double> eta = coat.material.index(lambda, options.interpolation, options.out_of_range);
            require_coat_index(coat, lambda, eta.real());
            o.has_coat = true;
            o.coat_index = eta.real();
            if (coat.thickness_nm)
                o.coat_absorbance = 4.0 * std::numbers::pi * std::max(eta.imag(), 0.0) * *coat.thickness_nm / lambda;
        }
        grid.push_back(o);
    }
    return grid;
}

std::vector<std::string> layer_held_constant(const LayerStack& layers, const WavelengthRange& needed,
                                             const SpectralOptions& options) {
    std::vector<std::string> notes;
    const auto add = [&](const char* layer, const LayerMaterial& m) {
        for (const std::string& note : held_constant_ranges(m, needed, options))
            notes.push_back(layer_label(layer, m) + ": " + note);
    };
    if (layers.film) add("film", layers.film->material);
    if (layers.coat) add("coat", layers.coat->material);
    return notes;
}

}  // namespace metalfit
