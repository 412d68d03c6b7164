#include "glpreview/render/dfg_table.hpp"

#include <algorithm>
#include <cmath>

#include "glpreview/render/ggx.hpp"

namespace metalfit::glpreview {

RGB dfg_integral(const SphereFresnel& fresnel, double mu_in, double roughness, int samples) {
    const double alpha = ggx::alpha(roughness);
    if (alpha == 0) return fresnel(mu_in);  // the mirror: F(μ) itself
    const double mu = std::clamp(mu_in, 1e-4, 1.0);
    const Vec3 v{std::sqrt(1.0 - mu * mu), 0, mu};
    RGB sum{0, 0, 0};
    const auto n = static_cast<unsigned>(samples);
    for (unsigned i = 0; i < n; ++i) {
        double u1, u2;
        ggx::hammersley(i, n, u1, u2);
        const ggx::LobeSample s = ggx::sample_reflection(v, alpha, u1, u2);
        if (s.weight <= 0) continue;
        const RGB f = fresnel(s.cos_d);
        sum = {sum.r + s.weight * f.r, sum.g + s.weight * f.g, sum.b + s.weight * f.b};
    }
    return {sum.r / samples, sum.g / samples, sum.b / samples};
}

DfgTable make_dfg_table(const SphereFresnel& fresnel) {
    DfgTable table;
    table.values.resize(static_cast<std::size_t>(DfgTable::kMuSize) * DfgTable::kRoughnessSize);
    for (int j = 0; j < DfgTable::kRoughnessSize; ++j)
        for (int i = 0; i < DfgTable::kMuSize; ++i)
            table.values[static_cast<std::size_t>(j) * DfgTable::kMuSize + i] =
                dfg_integral(fresnel, i / double(DfgTable::kMuSize - 1), j / double(DfgTable::kRoughnessSize - 1));
    return table;
}

RGB DfgTable::operator()(double mu, double roughness) const {
    const double x = std::clamp(mu, 0.0, 1.0) * (kMuSize - 1);
    const double y = std::clamp(roughness, 0.0, 1.0) * (kRoughnessSize - 1);
    const int i = std::min(static_cast<int>(x), kMuSize - 2), j = std::min(static_cast<int>(y), kRoughnessSize - 2);
    const double fx = x - i, fy = y - j;
    auto mix = [](const RGB& a, const RGB& b, double t) {
        return RGB{a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b)};
    };
    return mix(mix(at(i, j), at(i + 1, j), fx), mix(at(i, j + 1), at(i + 1, j + 1), fx), fy);
}

}  // namespace metalfit::glpreview
