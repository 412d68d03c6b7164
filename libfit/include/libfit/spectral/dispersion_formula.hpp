// Analytic dispersion formulas of the refractiveindex.info database (Sellmeier forms).
#pragma once

#include <vector>

#include "libfit/spectral/spectrum.hpp"

namespace metalfit {

// refractiveindex.info "formula 1" and "formula 2", λ in micrometres:
//   formula 1: n² − 1 = C1 + Σᵢ C(2i) λ² / (λ² − C(2i+1)²)
//   formula 2: n² − 1 = C1 + Σᵢ C(2i) λ² / (λ² − C(2i+1))
class SellmeierFormula {
public:
    enum class Form { squared_poles = 1, linear_poles = 2 };

    // coefficients: C1, C2, C3, ... (an odd count; a missing last pole is read as 0).
    SellmeierFormula(Form form, std::vector<double> coefficients, WavelengthRange valid_nm);

    double operator()(double nm, OutOfRange out_of_range = OutOfRange::error) const;
    WavelengthRange range() const { return valid_nm_; }
    Form form() const { return form_; }

private:
    Form form_;
    std::vector<double> c_;
    WavelengthRange valid_nm_;
};

}  // namespace metalfit
