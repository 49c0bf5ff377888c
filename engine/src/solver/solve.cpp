#include "radiant/solve.h"

namespace radiant {

// Placeholder until the pipeline lands: reports failure honestly rather than a fake answer.
Result solve(const Scene& scene, const SolveOptions& /*options*/, SolveObserver* /*observer*/,
             const CancellationToken* /*cancel*/) {
    Result r;
    r.scene = scene.name;
    r.status = SolveStatus::failed;
    r.error = "solver not implemented yet";
    return r;
}

SolveOptions options_from(const Settings& settings) {
    SolveOptions o;
    o.tolerance = settings.tolerance;
    o.max_seconds = settings.max_seconds;
    o.method = settings.method;
    return o;
}

const std::vector<std::string>& solver_names() {
    static const std::vector<std::string> names{"auto", "direct", "jacobi", "gauss-seidel",
                                                "shooting"};
    return names;
}

const char* to_string(SolveStatus status) {
    switch (status) {
        case SolveStatus::converged: return "converged";
        case SolveStatus::stopped: return "stopped";
        case SolveStatus::failed: return "failed";
    }
    return "failed";
}

}  // namespace radiant
