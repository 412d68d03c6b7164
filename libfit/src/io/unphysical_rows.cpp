#include "io/unphysical_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "libfit/base/number_text.hpp"

namespace metalfit::detail {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Side {
    const UnphysicalRow* row = nullptr;  // the dropped row nearest the visible range on this side
    bool below = true;                   // below 360 nm (else above 830 nm)
};

// The bad row of `curve` (bit) nearest the visible range below it (`below`) or above it; nullptr when none.
const UnphysicalRow* nearest(const std::vector<UnphysicalRow>& bad, unsigned curve, bool below) {
    const UnphysicalRow* found = nullptr;
    for (const UnphysicalRow& r : bad) {
        if (!(r.curves & curve)) continue;
        if (below ? r.nm < kVisibleRange.min_nm && (!found || r.nm > found->nm)
                  : r.nm > kVisibleRange.max_nm && (!found || r.nm < found->nm))
            found = &r;
    }
    return found;
}

}  // namespace

UnphysicalTrim drop_unphysical_ends(const std::vector<UnphysicalRow>& bad, std::vector<SpectrumSample>& n,
                                    std::vector<SpectrumSample>& k, double unit_per_nm, const char* unit) {
    UnphysicalTrim trim;
    if (bad.empty()) return trim;
    for (const UnphysicalRow& r : bad)
        if (r.nm >= kVisibleRange.min_nm && r.nm <= kVisibleRange.max_nm) throw r.error;
    const auto text = [&](double nm) { return significant_text(nm * unit_per_nm, 6) + " " + unit; };

    std::vector<const UnphysicalRow*> named;
    for (auto [curve, samples, kept, what] : {std::tuple{1u, &n, &trim.n, "n"}, std::tuple{2u, &k, &trim.k, "k"}}) {
        const UnphysicalRow* low = nearest(bad, curve, true);
        const UnphysicalRow* high = nearest(bad, curve, false);
        kept->after_nm = low ? low->nm : -kInfinity;
        kept->before_nm = high ? high->nm : kInfinity;
        // The samples that bracket 360 and 830 nm must be valid ones: a valid sample between the bad row and the range.
        const auto has = [&](double from, double to) {
            return std::any_of(samples->begin(), samples->end(), [&](const SpectrumSample& s) {
                return s.wavelength_nm >= from && s.wavelength_nm <= to;
            });
        };
        if (low && !has(std::nextafter(low->nm, kInfinity), kVisibleRange.min_nm)) throw low->error;
        if (high && !has(kVisibleRange.max_nm, std::nextafter(high->nm, -kInfinity))) throw high->error;
        std::erase_if(*samples, [&](const SpectrumSample& s) { return !kept->keeps(s.wavelength_nm); });
        if (samples->empty()) continue;
        const auto [lo, hi] =
            std::minmax_element(samples->begin(), samples->end(), [](const SpectrumSample& a, const SpectrumSample& b) {
                return a.wavelength_nm < b.wavelength_nm;
            });
        for (const UnphysicalRow* row : {low, high}) {
            if (!row || std::find(named.begin(), named.end(), row) != named.end()) continue;
            named.push_back(row);
            const std::string curves = row->curves == 3u ? "n and k" : what;
            trim.warnings.push_back(std::string(row->error.what()) + " at " + text(row->nm) + ": rows " +
                                    (row == low ? "up to " : "from ") + text(row->nm) + (row == low ? "" : " on") +
                                    " are not used (colour needs " + significant_text(kVisibleRange.min_nm, 6) +
                                    "\xe2\x80\x93" + significant_text(kVisibleRange.max_nm, 6) + " nm; " + curves +
                                    " kept over " + significant_text(lo->wavelength_nm * unit_per_nm, 6) +
                                    "\xe2\x80\x93" + text(hi->wavelength_nm) + ")");
        }
    }
    return trim;
}

}  // namespace metalfit::detail
