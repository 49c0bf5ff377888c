// The variance of a mean, estimated from the values it is the mean of.
#pragma once

namespace radiant {

/// The unbiased estimate of the variance of the mean of `n` independent values (0 for fewer
/// than two).
inline double sample_variance_of_mean(const double* values, int n) {
    if (n < 2) return 0;
    double mean = 0;
    for (int k = 0; k < n; ++k) mean += values[k];
    mean /= n;
    double sum = 0;
    for (int k = 0; k < n; ++k) sum += (values[k] - mean) * (values[k] - mean);
    return sum / (static_cast<double>(n) * (n - 1));
}

}  // namespace radiant
