// One Jacobi sweep B' = S + diag(ρ)·R·B over the rows R of the form-factor matrix, computed one
// by one as matrix-free shooting computes them: how that shooting ends when its unshot light has
// both signs.
//
// Over-relaxed shots leave negative unshot light on the patches that shot and positive light on
// the rest. The shooter's bound counts |unshot| (an area-weighted L1 norm), while light of
// opposite signs cancels where it lands: on a closed sphere the bound was 5.5 times the error.
// The sweep computes the residual r = S + diag(ρ)·R·B − B with its signs, after that cancellation,
// and moves B one step on: B' − B* = M(B − B*) with M = diag(ρ)·R, so in either norm
// ‖B' − B*‖ ≤ q‖r‖ / (1 − q), q the norm of M measured on the rows themselves (the largest
// ρ_i Σ_j R_ij, and the largest Σ_i A_i ρ_i R_ij / A_j), as relative_error_bound combines them.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "solver/linear_system.h"
#include "solver/solver.h"

namespace radiant {

class Transport;

struct GatherSweep {
    std::array<std::vector<double>, 3> radiosity;  ///< B' per channel
    std::array<std::vector<double>, 3> gathered;   ///< R·B per channel: reflected irradiance
    double error_bound = 0;                        ///< of B', relative as relative_error_bound's
    std::uint64_t factors = 0;                     ///< non-zero factors computed
    bool complete = false;  ///< false when the control stopped it before the last row
};

/// The sweep from `radiosity` (per channel, `system.form_factors` unused). Rays are added to
/// `rays`; every 100 ms `control.progress` is called with (`shots`, the estimate it replaces,
/// `unshot_fraction`). The rows are the same whatever the thread count, and so is the result.
GatherSweep gather_sweep(const LinearSystem& system, const Transport& transport,
                         const std::array<std::vector<double>, 3>& radiosity,
                         const SolverControl& control, std::size_t shots, double estimate,
                         double unshot_fraction, std::uint64_t& rays);

}  // namespace radiant
