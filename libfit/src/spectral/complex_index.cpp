#include "libfit/spectral/complex_index.hpp"

#include <algorithm>
#include <limits>

namespace metalfit {

double SpectralCurve::operator()(double nm, Interpolation interpolation, OutOfRange out_of_range) const {
    struct Visitor {
        double nm;
        Interpolation interpolation;
        OutOfRange out_of_range;
        double operator()(const Spectrum& s) const { return s(nm, interpolation, out_of_range); }
        double operator()(const SellmeierFormula& f) const { return f(nm, out_of_range); }
        double operator()(const ConstantSpectrum& c) const { return c.value; }
    };
    return std::visit(Visitor{nm, interpolation, out_of_range}, curve_);
}

WavelengthRange SpectralCurve::range() const {
    struct Visitor {
        WavelengthRange operator()(const Spectrum& s) const { return s.range(); }
        WavelengthRange operator()(const SellmeierFormula& f) const { return f.range(); }
        WavelengthRange operator()(const ConstantSpectrum&) const {
            return {0.0, std::numeric_limits<double>::infinity()};
        }
    };
    return std::visit(Visitor{}, curve_);
}

std::size_t SpectralCurve::tabulated_points_in(const WavelengthRange& r) const {
    const Spectrum* s = tabulated();
    return s ? s->count_in(r) : 0;
}

std::string SpectralCurve::kind() const {
    struct Visitor {
        std::string operator()(const Spectrum&) const { return "tabulated"; }
        std::string operator()(const SellmeierFormula& f) const {
            return f.form() == SellmeierFormula::Form::squared_poles ? "formula 1" : "formula 2";
        }
        std::string operator()(const ConstantSpectrum&) const { return "constant"; }
    };
    return std::visit(Visitor{}, curve_);
}

WavelengthRange ComplexIndex::range() const {
    const WavelengthRange a = n.range(), b = k.range();
    return {std::max(a.min_nm, b.min_nm), std::min(a.max_nm, b.max_nm)};
}

}  // namespace metalfit
