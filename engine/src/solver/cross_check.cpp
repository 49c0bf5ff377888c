// The cross-check stage of the pipeline: a radiosity answer in a cluttered room measured against
// a Monte Carlo solve of the same prepared scene.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "solution/result_difference.h"
#include "solver/pipeline.h"

namespace radiant {
namespace {

// The Monte Carlo solve resolves this share of the radiosity answer's estimate (or of the
// tolerance, where that is smaller): its own estimate is part of the bound, so it must be small
// beside the error measured — but its cost grows as 1/tolerance², so it stops at a sixteenth of
// the tolerance and at kMinCrossCheckTolerance (at 0.002 it took 55 s of the furnished office's
// 122 without sensors, 23 s of the open plan's 29).
constexpr double kCrossCheckResolution = 8;
constexpr double kMaxCrossCheckResolution = 16;
constexpr double kMinCrossCheckTolerance = 0.003;
// Monte Carlo's estimate comes out at about half its tolerance or more: a method's own estimate
// under that share (the dense paths' at fine tolerances, the sphere's matrix-free shooting)
// cannot be lowered by the check, which is then not run.
constexpr double kLeastMonteCarloShare = 0.5;
// With d the distance and e Monte Carlo's estimate, the answer's error lies between d − e and
// d + e: where that bound may be more than kLooseBound times the error (e above a third of d),
// the check's noise is most of it and a finer solve, at a quarter of its tolerance, tightens it,
// if its rays (which grow as 1/tolerance²) and the passes' before it come to no more than
// kCheckRaysShare times the radiosity solve's own — rays, not seconds, so that the answer does
// not depend on the machine. Dense shooting on office-x4 at 0.3: d + e was 4.2 % for an error of
// 0.36 %, with e under d; hierarchical at 0.1 there, 0.67 % for 0.125 % while the checks could
// cast no more rays than the solve.
constexpr double kLooseBound = 2;
constexpr double kCheckRaysShare = 4;
constexpr double kFinerPassRatio = 4;

// `result` without its maintenance factor, as the radiosity paths hold their answer until
// finish_lighting applies it (they solve scenes with one light component only).
Result unmaintained(Result result, const PreparedScene& scene) {
    const auto& components = scene.components.components;
    const double mf = components.size() == 1 ? components.front().maintenance_factor : 1.0;
    if (mf == 1 || !(mf > 0)) return result;
    for (SensorResult& set : result.sensors) {
        for (double& e : set.illuminance) e /= mf;
    }
    for (SurfaceResult& s : result.surfaces) {
        s.average_irradiance /= mf;
        s.average_radiosity /= mf;
    }
    return result;
}

}  // namespace

void Pipeline::cross_check(const PreparedSolve& prepared, Result& result) {
    const double own = result.stats.error_estimate;
    double tolerance =
        std::max({std::min(options_.tolerance, own) / kCrossCheckResolution,
                  options_.tolerance / kMaxCrossCheckResolution, kMinCrossCheckTolerance});
    const bool replaces = result.stats.method == "hierarchical";
    if (!replaces && own <= kLeastMonteCarloShare * tolerance) return;
    report("cross-checking", 0.97, result.stats.iterations, std::nullopt,
           result.stats.unshot_fraction);
    const std::uint64_t solve_rays = rays_;
    double check_rays = 0;
    double bound = 0;
    for (bool first = true;; first = false) {
        SolveOptions options = options_within_deadline(tolerance);
        options.want_mesh = false;
        Pipeline check(*this, options);
        const Result mc = check.run_monte_carlo(prepared);
        rays_ += check.rays_;
        check_rays += static_cast<double>(check.rays_);
        result.stats.rays = rays_;
        result.stats.seconds = elapsed();
        if (!check.memory_stop_.empty()) stop_for_memory(check.memory_stop_);
        // A Monte Carlo solve that stopped short of its tolerance still bounds its error by its
        // estimate; one that failed, or stopped (time limit, cancel) before it had one, leaves
        // nothing to vouch for the answer's.
        if (mc.status == SolveStatus::failed || !std::isfinite(mc.stats.error_estimate)) {
            if (!first) break;  // the previous pass's bound stands
            result.status = SolveStatus::stopped;
            if (!mc.error.empty())
                result.stop_reason = "the Monte Carlo cross-check failed: " + mc.error;
            return;
        }
        const double distance = relative_rms_difference(unmaintained(mc, prepared.scene), result);
        bound = distance + mc.stats.error_estimate;
        const double lower = distance - mc.stats.error_estimate;
        const double finer = std::max(tolerance / kFinerPassRatio, kMinCrossCheckTolerance);
        const double rays_ratio = (tolerance / finer) * (tolerance / finer);
        if (!(bound > kLooseBound * lower) || !(finer < tolerance) ||
            check_rays + static_cast<double>(check.rays_) * rays_ratio >
                kCheckRaysShare * static_cast<double>(solve_rays) ||
            should_stop()) {
            break;
        }
        tolerance = finer;
    }
    result.stats.error_parts.cross_check = bound;
    // The dense paths' own estimates bound their error (every validation scene and benchmark
    // row), so the smaller bound stands; the hierarchical one can be under its error among
    // close objects (docs/accuracy.md, "Bookshelves"), so the cross-check replaces it.
    result.stats.error_estimate = replaces ? bound : std::min(own, bound);
    if (should_stop()) {
        result.status = SolveStatus::stopped;
        return;
    }
    // Measured, the answer is as good as its bound says, whatever the solver's own estimate had
    // claimed: a hierarchical solve stopped for the light its links made is `converged` if the
    // check finds it within the tolerance.
    result.stop_reason.clear();
    result.status = SolveStatus::converged;
    if (!(result.stats.error_estimate <= options_.tolerance)) {
        char share[32];
        std::snprintf(share, sizeof share, "%.2g %%", 100 * bound);
        result.status = SolveStatus::stopped;
        result.stop_reason = "a Monte Carlo solve puts the " + result.stats.method +
                             " answer within " + share +
                             ", more than the tolerance; the monte-carlo method (what auto picks "
                             "for cluttered rooms) meets it";
    }
}

}  // namespace radiant
