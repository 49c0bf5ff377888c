// How far a Monte Carlo answer may be from the truth, from its own data; and how many more
// samples bring it within the tolerance at the least cost.
#pragma once

#include <cstddef>
#include <vector>

#include "montecarlo/sensor_gather.h"
#include "radiant/result.h"

namespace radiant {

struct MonteCarloError {
    double total = 0;  ///< the estimate: RMS over a set's points relative to its mean, worst set
    ErrorParts parts;  ///< of the worst set
    /// Whether the discretisation part stands out of its own noise (see set_errors): only then
    /// does a finer mesh promise less of it, rather than more samples.
    bool discretisation_significant = false;
};

/// The estimate of every sensor set (relative to its mean; 0 for a set without light), and
/// its mean (lux); `set_sizes` splits the points into sensor sets.
struct SetError {
    MonteCarloError error;
    double mean = 0;
};
std::vector<SetError> set_errors(const std::vector<GatheredPoint>& points,
                                 const std::vector<std::size_t>& set_sizes);

/// The worst of the sets' errors (sets without light aside), each scaled by `scale`.
MonteCarloError worst_error(const std::vector<SetError>& sets, double scale = 1);

struct SampleBudget {
    std::size_t photons = 0;
    int sets = 0;  ///< ray sets per sensor point
};

/// The least-cost budget whose expected error is within `target`: noise falls as 1/√samples,
/// so photons and ray sets are raised in proportion to how much of the error each explains
/// and to how little it costs (Lagrange's optimum for cost = c_p·photons + c_s·sets), each by
/// at most kMaxGrowth per round and never lowered. Bias does not fall with samples; what it
/// leaves of `target` is what the noise may take.
SampleBudget next_budget(const MonteCarloError& error, const SampleBudget& now, double target,
                         double seconds_per_photon, double seconds_per_set);

}  // namespace radiant
