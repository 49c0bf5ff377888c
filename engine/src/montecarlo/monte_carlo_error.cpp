#include "montecarlo/monte_carlo_error.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "montecarlo/chi_square_margin.h"
#include "montecarlo/sample_variance.h"

namespace radiant {
namespace {

// The noise parts are measured standard deviations; these margins make the estimate a bound
// on the realised error rather than its expectation (the spread of a few ray sets or sixteen
// batches is itself uncertain, and neighbouring points read the same elements, so a set's RMS
// averages their photon noise less than independent noise).
constexpr double kGatherMargin = 1.5;
constexpr double kPhotonMargin = 1.5;
// The photon noise every point of a set shares (the field read the same everywhere) is one
// draw, not an average over the set's points: its margin is a normal's two-sided 95 %.
constexpr double kSharedPhotonMargin = 2;
// A set's noise is a sum over its points; where a few of them hold most of its variance (points
// beside lamps, or a set of one point) the realised RMS is a draw of few degrees of freedom, and
// the margins above leave it under its estimate far more often: one lounge seed in ten at
// tolerance 0.05 (0.75 times its error, from one point by a lamp), and a single point one time
// in eight. The margins are then at least chi_square_margin of the points' effective count
// (2.57 for one point; from about ten points on, the margins above hold).
// A budget grows at most this much per round, so that a poor first variance cannot send the
// solve far past its tolerance, and so that a discretisation part that stands out of its noise
// only with more samples is seen before most of them are spent on a mesh that is then
// refined: at 8 times, the living room's second round at 0.01 (64 ray sets per point) showed
// it, and the finer level started afresh (17 M rays in all); at 3 times, the third round's
// estimate met the tolerance on the first mesh (6.3 M rays, true error 0.76 % for 0.80 %).
constexpr double kMaxGrowth = 3;
// When the model says the budget suffices but the estimate still misses the target, the
// larger noise part's samples grow by this.
constexpr double kMinGrowth = 1.5;
// The far hits' depth check (GatheredPoint::depth_difference_squared) counts only where the
// set's squared differences exceed their noise by this many of that excess's own standard
// deviations: a set of one point reads a single noisy difference, whose square exceeds its
// variance one time in three, and a scene has many such sets and rounds (the example office's
// desk points made its mesh 3.6 times finer at tolerance 0.01 for no better answer; at two
// deviations, still 4 times at 0.003). The coarser level's difference always counts, but calls
// for a finer mesh only when it stands out so: office-x4 at 0.0007 read 0.098 % of it in the
// first round of each level, from photon noise of 1 % per point, and refined three times to
// `stopped` in 4 s, where its first mesh, sampled as the tolerance asks, shows 0.048 %.
constexpr double kBiasSignificance = 3;
// The coarser level joins each element with its sibling: twice the area, √2 times the size.
// Reading element averages is biased at first order in the size where elements straddle edges
// of light and of sight at once (the contact lines of clutter: books on a board, a case's
// corners), so the fine level's bias is the levels' difference over √2 − 1. Taken as it was,
// the difference put a library's spines 0.14 % dark under a discretisation part of 0.069 %;
// elements of 0.4 times the size moved them 0.1 % (tests/bench/results/library.md).
const double kCoarseToBias = 1 / (std::sqrt(2.0) - 1);
// Bias may take this much of the target² before the noise budget is held to what it leaves.
constexpr double kMinNoiseShare = 0.1;

}  // namespace

std::vector<SetError> set_errors(const std::vector<GatheredPoint>& points,
                                 const std::vector<std::size_t>& set_sizes) {
    std::vector<SetError> out;
    std::size_t first = 0;
    for (const std::size_t size : set_sizes) {
        SetError& set = out.emplace_back();
        double mean = 0, gather = 0, photon = 0, bias = 0, bias_noise = 0;
        double depth = 0, depth_noise = 0;  // Σ (d² − var) and Σ var², over the set
        double noise_squares = 0;           // Σ (gather + photon variance)², over the set
        std::array<double, PhotonField::kBatches> shared{};  // the set's mean, batch by batch
        for (std::size_t i = first; i < first + size; ++i) {
            mean += points[i].illuminance;
            gather += points[i].gather_variance;
            photon += points[i].photon_variance;
            const double noise = points[i].gather_variance + points[i].photon_variance;
            noise_squares += noise * noise;
            bias += points[i].coarse_difference_squared - points[i].coarse_difference_variance;
            bias_noise +=
                points[i].coarse_difference_variance * points[i].coarse_difference_variance;
            const double var = points[i].depth_difference_variance;
            depth += points[i].depth_difference_squared - var;
            depth_noise += var * var;
            for (int q = 0; q < PhotonField::kBatches; ++q)
                shared[static_cast<std::size_t>(q)] +=
                    points[i].photon_batches[static_cast<std::size_t>(q)];
        }
        first += size;
        // (d² − var has a standard deviation of √2·var for a normal d.)
        const bool deep = depth > kBiasSignificance * std::sqrt(2 * depth_noise);
        set.error.discretisation_significant =
            deep || bias > kBiasSignificance * std::sqrt(2 * bias_noise);
        bias *= kCoarseToBias * kCoarseToBias;
        if (deep) bias += depth;
        if (size == 0 || !(mean > 0)) continue;
        const double n = static_cast<double>(size);
        mean /= n;
        set.mean = mean;
        MonteCarloError& e = set.error;
        const double points_worth =
            noise_squares > 0 ? (gather + photon) * (gather + photon) / noise_squares : n;
        e.parts.gather_noise =
            std::max(kGatherMargin, chi_square_margin(points_worth)) * std::sqrt(gather / n) / mean;
        // The points' mean photon variance is the shared part's plus the rest's, which
        // averages over the points.
        for (double& v : shared) v /= n;
        const double shared_variance =
            sample_variance_of_mean(shared.data(), PhotonField::kBatches);
        const double own_variance = std::max(0.0, photon / n - shared_variance);
        const double own_margin = std::max(kPhotonMargin, chi_square_margin(points_worth));
        e.parts.photon_noise =
            std::sqrt(own_margin * own_margin * own_variance +
                      kSharedPhotonMargin * kSharedPhotonMargin * shared_variance) /
            mean;
        e.parts.discretisation = std::sqrt(std::max(0.0, bias) / n) / mean;
        e.total = std::sqrt(e.parts.gather_noise * e.parts.gather_noise +
                            e.parts.photon_noise * e.parts.photon_noise +
                            e.parts.discretisation * e.parts.discretisation);
    }
    return out;
}

MonteCarloError worst_error(const std::vector<SetError>& sets, double scale) {
    MonteCarloError worst;
    for (const SetError& set : sets) {
        if (!(set.mean > 0)) continue;
        MonteCarloError e = set.error;
        e.total *= scale;
        e.parts.gather_noise *= scale;
        e.parts.photon_noise *= scale;
        e.parts.discretisation *= scale;
        if (!(e.total <= worst.total)) worst = e;
    }
    return worst;
}

SampleBudget next_budget(const MonteCarloError& error, const SampleBudget& now, double target,
                         double seconds_per_photon, double seconds_per_set) {
    const double g = error.parts.gather_noise, f = error.parts.photon_noise;
    const double b = error.parts.discretisation;
    const double noise = std::max(target * target - b * b, kMinNoiseShare * target * target);
    const double cost_set = std::max(seconds_per_set, 1e-12);
    const double cost_photon = std::max(seconds_per_photon, 1e-15);
    const double a_set = g * g * now.sets, a_photon = f * f * static_cast<double>(now.photons);
    const double lagrange = std::sqrt(a_set * cost_set) + std::sqrt(a_photon * cost_photon);
    const double sets = std::sqrt(a_set / cost_set) * lagrange / noise;
    const double photons = std::sqrt(a_photon / cost_photon) * lagrange / noise;
    SampleBudget next;
    next.sets = static_cast<int>(
        std::clamp(std::ceil(sets), static_cast<double>(now.sets), kMaxGrowth * now.sets));
    next.photons =
        static_cast<std::size_t>(std::clamp(std::ceil(photons), static_cast<double>(now.photons),
                                            kMaxGrowth * static_cast<double>(now.photons)));
    if (next.sets == now.sets && next.photons == now.photons) {
        if (g >= f) {
            next.sets = static_cast<int>(std::ceil(kMinGrowth * now.sets));
        } else {
            next.photons =
                static_cast<std::size_t>(std::ceil(kMinGrowth * static_cast<double>(now.photons)));
        }
    }
    return next;
}

}  // namespace radiant
