#include "libfit/fit/reflectance_target.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "libfit/base/number_text.hpp"

namespace metalfit {

namespace {

std::vector<ReflectanceRow> checked(std::vector<ReflectanceRow> rows, const std::filesystem::path& file) {
    const auto fail = [&file](std::size_t row, const std::string& why) {
        throw InputError(InputLocation(file, static_cast<int>(row + 1)), why);
    };
    if (rows.size() < 2) fail(0, "a measured reflectance needs at least two rows (mu = 0 and 1)");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const ReflectanceRow& r = rows[i];
        if (!std::isfinite(r.mu) || !std::isfinite(r.value.r) || !std::isfinite(r.value.g) || !std::isfinite(r.value.b))
            fail(i, "mu and R, G, B must be finite numbers");
        if (i > 0 && !(r.mu > rows[i - 1].mu))
            fail(i, "mu = " + significant_text(r.mu, 6) + " does not increase (the row before has " +
                        significant_text(rows[i - 1].mu, 6) + ")");
    }
    if (rows.front().mu != 0) fail(0, "the first row's mu is " + significant_text(rows.front().mu, 6) + ", not 0");
    if (rows.back().mu != 1)
        fail(rows.size() - 1, "the last row's mu is " + significant_text(rows.back().mu, 6) + ", not 1");
    return rows;
}

}  // namespace

RGB interpolate_reflectance(const std::vector<ReflectanceRow>& rows, double mu) {
    if (!(mu > rows.front().mu)) return rows.front().value;  // below the first row (or NaN): its value
    if (!(mu < rows.back().mu)) return rows.back().value;
    // The first row with μ_i ≥ μ: an exact row's own value, else linear between it and the one before.
    const auto after =
        std::lower_bound(rows.begin(), rows.end(), mu, [](const ReflectanceRow& r, double m) { return r.mu < m; });
    if (after->mu == mu) return after->value;
    const ReflectanceRow& a = *(after - 1);
    const ReflectanceRow& b = *after;
    const double t = (mu - a.mu) / (b.mu - a.mu);
    return {a.value.r + t * (b.value.r - a.value.r), a.value.g + t * (b.value.g - a.value.g),
            a.value.b + t * (b.value.b - a.value.b)};
}

ReflectanceTarget::ReflectanceTarget(std::string id, std::filesystem::path file, std::vector<ReflectanceRow> rows,
                                     const Colorimetry& colorimetry, const ColorSpaceConverter& converter,
                                     const ErrorSettings& error)
    : id_(std::move(id)),
      file_(std::move(file)),
      rows_(std::make_shared<const std::vector<ReflectanceRow>>(checked(std::move(rows), file_))) {
    const auto curve = [rows = rows_](std::span<const double> mu) {
        std::vector<RGB> values;
        values.reserve(mu.size());
        for (const double m : mu) values.push_back(interpolate_reflectance(*rows, m));
        return values;
    };
    reference_ = std::make_shared<const SampledReference>(curve, converter, converter(colorimetry.white()), error);
}

RGB ReflectanceTarget::operator()(double mu) const { return interpolate_reflectance(*rows_, mu); }

std::string ReflectanceTarget::describe() const {
    return "measured reflectance " + id_ + " (" + std::to_string(rows_->size()) + " rows of mu, R, G, B)";
}

}  // namespace metalfit
