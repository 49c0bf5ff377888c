#include "checks/solve_outcome.h"

#include <cstdio>

namespace radiant {
namespace {

// A stage that cannot look at the clock (one Embree build, one refinement sweep) may run over
// the deadline a little; more than this is worth saying.
constexpr double kOverrunShare = 0.1;
constexpr double kOverrunSeconds = 0.5;

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

}  // namespace

void check_solve_outcome(const Result& result, const SolveOptions& options, bool cancelled,
                         std::vector<Warning>& out) {
    if (result.status == SolveStatus::failed || cancelled) return;
    const SolveStats& st = result.stats;
    const std::string estimate =
        "an error estimate of " + number(st.error_estimate) +
        (st.error_estimate > options.tolerance ? ", over the tolerance " : " (tolerance ") +
        number(options.tolerance) + (st.error_estimate > options.tolerance ? "" : ")");
    if (options.max_seconds) {
        const double limit = *options.max_seconds;
        const double overrun = st.seconds - limit;
        const std::string over = overrun > kOverrunShare * limit + kOverrunSeconds
                                     ? " and overran it by " + number(overrun) + " s"
                                     : "";
        if (result.status == SolveStatus::stopped && overrun >= 0) {
            out.push_back({"time_limit",
                           "the solve stopped at its time limit of " + number(limit) + " s" + over +
                               " with " + estimate + ": the answer is the best so far",
                           "/settings/max_seconds"});
            return;
        }
        if (!over.empty()) {
            out.push_back({"time_limit",
                           "the solve took " + number(st.seconds) +
                               " s: it reached its time "
                               "limit of " +
                               number(limit) + " s" + over,
                           "/settings/max_seconds"});
        }
    }
    if (result.status == SolveStatus::stopped) {
        // The memory budget may stop refinement with the estimate within the tolerance.
        out.push_back(
            {"not_converged",
             "the solve stopped with an error estimate of " + number(st.error_estimate) +
                 " (tolerance " + number(options.tolerance) + "): " +
                 (result.stop_reason.empty() ? "a memory, mesh or refinement limit came first"
                                             : result.stop_reason),
             "/settings/tolerance"});
    }
}

}  // namespace radiant
