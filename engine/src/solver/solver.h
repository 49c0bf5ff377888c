// The solver interface: every method solves the same LinearSystem, honours the same control
// (tolerance, deadline, cancellation) and reports the same statistics, so speed against error
// can be compared on one scene in one run.
#pragma once

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radiant/solve.h"
#include "solver/linear_system.h"

namespace radiant {

struct SolverControl {
    double tolerance = 0.01;  ///< stop when the error bound is at or below this
    std::optional<std::chrono::steady_clock::time_point> deadline;
    const CancellationToken* cancel = nullptr;
    /// Called now and then with (iterations, error estimate, unshot fraction).
    std::function<void(std::size_t, double, double)> progress;
    /// Called with the current radiosity (per channel) at most every `snapshot_interval`.
    std::function<void(const std::array<std::vector<double>, 3>&)> snapshot;
    std::chrono::duration<double> snapshot_interval{0.5};

    /// True (and `last` reset to now) when a snapshot is wanted and the interval has passed.
    bool snapshot_due(std::chrono::steady_clock::time_point& last) const {
        const auto now = std::chrono::steady_clock::now();
        if (!snapshot || now - last < snapshot_interval) return false;
        last = now;
        return true;
    }

    bool should_stop() const {
        return (cancel && cancel->cancelled()) ||
               (deadline && std::chrono::steady_clock::now() >= *deadline);
    }
};

struct SolverOutcome {
    std::array<std::vector<double>, 3> radiosity;  ///< per channel, lm/m²
    std::size_t iterations = 0;
    double error_estimate = 0;
    double unshot_fraction = 0;
    bool converged = false;
};

class Solver {
public:
    virtual ~Solver() = default;
    virtual std::string_view name() const = 0;
    /// Thread-safe for distinct systems; uses the calling thread's TBB arena for parallel loops.
    virtual SolverOutcome solve(const LinearSystem& system, const SolverControl& control) const = 0;
};

/// direct, jacobi, gauss-seidel, shooting; nullptr for an unknown name.
std::unique_ptr<Solver> make_solver(std::string_view name);

/// Σ_i A_i B_i over one channel.
double area_weighted_sum(const std::vector<double>& values, const std::vector<double>& area);

/// Over-relaxation factor ω for shooting from the area-weighted mean reflectance: 1 + ρ̄/2, at
/// most 1.5 (Feda & Purgathofer 1992 report gains growing with reflectivity; larger values
/// oscillate). A shot sends ω times what is unshot, anticipating what the patch will receive
/// back; unshot values may then turn negative.
double over_relaxation(double mean_reflectance);

/// Ambient term of Cohen et al. 1988 for display while shooting: the unshot exitance spread
/// over the scene and multiplied by the interreflection factor 1/(1 − ρ̄), ρ̄ area-weighted;
/// patch i is shown as B_i + ρ_i·seen_i·ambient. `seen` (per patch, the share of its hemisphere
/// that surfaces cover: its factors' sum; empty: 1, a closed scene) weights the areas, so that in
/// an open scene light that will escape is not shown as arriving. Display only; it never enters
/// the solution.
double ambient_term(const std::vector<double>& unshot, const std::vector<double>& reflectance,
                    const std::vector<double>& area, const std::vector<double>& seen = {});

}  // namespace radiant
