// The statistics of every measurement metalfit prints (CPU and GPU timings alike): medians, quantiles, and the ratio
// of two series sampled in the same rounds with its noise.
#pragma once

#include <vector>

namespace metalfit {

double median(std::vector<double> values);              // average of the middle two for an even count; NaN if empty
double quantile(std::vector<double> values, double q);  // linear interpolation between order statistics; NaN if empty

struct Ratio {
    double median = 0;  // median over rounds of a[r] / b[r]
    double noise = 0;   // half the interquartile range of the same ratios
};
// a[r] / b[r] over the rounds both have.
Ratio paired_ratio(const std::vector<double>& a, const std::vector<double>& b);

// Spearman's rank correlation of two series of the same length (the Pearson correlation of their ranks, tied values
// sharing the mean of their ranks): 1 when b orders the items as a does, −1 when reversed. NaN for fewer than two
// items, different lengths or a constant series.
double spearman(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace metalfit
