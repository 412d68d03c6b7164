#include "libfit/base/sample_statistics.hpp"

#include <algorithm>
#include <limits>

namespace metalfit {

double quantile(std::vector<double> values, double q) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(values.begin(), values.end());
    const double x = q * static_cast<double>(values.size() - 1);
    const std::size_t i = static_cast<std::size_t>(x);
    if (i + 1 >= values.size()) return values.back();
    return values[i] + (x - static_cast<double>(i)) * (values[i + 1] - values[i]);
}

double median(std::vector<double> values) { return quantile(std::move(values), 0.5); }

Ratio paired_ratio(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> r;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) r.push_back(a[i] / b[i]);
    return {median(r), 0.5 * (quantile(r, 0.75) - quantile(r, 0.25))};
}

}  // namespace metalfit
