// A reference made of independent runs of a noisy renderer: per point, their mean or their
// median, and its standard error.
#pragma once

#include <vector>

namespace radiant::bench {

struct CombinedRuns {
    std::vector<double> value;
    /// Of the mean, from the runs' spread (NaN for a single run); of a median, √(π/2) times
    /// that (the normal case's ratio), the spread measured by the median absolute deviation so
    /// that one run's outlier does not set it.
    std::vector<double> standard_error;
};

/// `runs[k][i]`: run k's value at point i; every run has the same points. The median resists a
/// rare bright path that one run samples (a mean of a few runs moves by per cents with it).
CombinedRuns combine_runs(const std::vector<std::vector<double>>& runs, bool median);

}  // namespace radiant::bench
