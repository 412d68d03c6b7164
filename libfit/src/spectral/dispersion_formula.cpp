#include "libfit/spectral/dispersion_formula.hpp"

#include <cmath>
#include <stdexcept>

namespace metalfit {

SellmeierFormula::SellmeierFormula(Form form, std::vector<double> coefficients, WavelengthRange valid_nm)
    : form_(form), c_(std::move(coefficients)), valid_nm_(valid_nm) {
    if (c_.empty()) throw std::invalid_argument("a Sellmeier formula needs coefficients");
    if (c_.size() % 2 == 0) c_.push_back(0.0);  // C1 + pairs (C2i, C2i+1)
}

double SellmeierFormula::operator()(double nm, OutOfRange out_of_range) const {
    if (!valid_nm_.contains(nm)) {
        if (out_of_range == OutOfRange::error || std::isnan(nm)) throw SpectrumRangeError(nm, valid_nm_);
        nm = nm < valid_nm_.min_nm ? valid_nm_.min_nm : valid_nm_.max_nm;
    }
    const double um = nm * 1e-3;
    const double l2 = um * um;
    double n2 = 1.0 + c_[0];
    for (std::size_t i = 1; i + 1 < c_.size(); i += 2) {
        const double pole = form_ == Form::squared_poles ? c_[i + 1] * c_[i + 1] : c_[i + 1];
        n2 += c_[i] * l2 / (l2 - pole);
    }
    return std::sqrt(n2);
}

}  // namespace metalfit
