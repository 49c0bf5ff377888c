// Solving a test scene with a chosen method and tolerance, and saying how the solve went.
#pragma once

#include <string>

#include "radiant/solve.h"

namespace radiant::testing {

/// Solves `scene` with its own settings, but `method` at `tolerance`.
inline Result solve_with(const Scene& scene, const std::string& method, double tolerance = 0.01) {
    SolveOptions options = options_from(scene.settings);
    options.method = method;
    options.tolerance = tolerance;
    return solve(scene, options);
}

inline Result solve_hierarchical(const Scene& scene, double tolerance = 0.01) {
    return solve_with(scene, "hierarchical", tolerance);
}

/// One line for failure messages: status, method, size, iterations, estimate and time.
inline std::string describe(const Result& r) {
    return std::string(to_string(r.status)) + " " + r.error + " (" + r.stats.method + ", " +
           std::to_string(r.stats.elements) + " elements, " + std::to_string(r.stats.links) +
           " links, " + std::to_string(r.stats.iterations) + " iterations, estimate " +
           std::to_string(r.stats.error_estimate) + ", " + std::to_string(r.stats.seconds) + " s)";
}

}  // namespace radiant::testing
