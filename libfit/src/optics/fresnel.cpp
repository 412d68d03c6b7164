#include "libfit/optics/fresnel.hpp"

#include <algorithm>

namespace metalfit {

FresnelReflectance fresnel_reflectance(double mu, std::complex<double> eta) {
    using C = std::complex<double>;
    if (eta == C(1.0, 0.0)) return {0.0, 0.0};  // no interface
    mu = std::clamp(mu, 0.0, 1.0);
    const double sin2 = (1.0 - mu) * (1.0 + mu);  // 1 − μ², without cancellation near μ = 1
    const C cos_t = std::sqrt(C(1.0, 0.0) - sin2 / (eta * eta));
    const C rs = (mu - eta * cos_t) / (mu + eta * cos_t);
    const C rp = (eta * mu - cos_t) / (eta * mu + cos_t);
    // |r|² can round to 1 + ulp under total internal reflection; the comparison keeps NaN visible.
    auto reflectance = [](C r) {
        const double f = std::norm(r);
        return f > 1.0 ? 1.0 : f;
    };
    return {reflectance(rs), reflectance(rp)};
}

double fresnel_normal_incidence(std::complex<double> eta) {
    const double n = eta.real(), k = eta.imag();
    return ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
}

}  // namespace metalfit
