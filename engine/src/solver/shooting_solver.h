// Progressive refinement (Cohen, Chen, Wallace & Greenberg 1988) in its residual form, i.e.
// Southwell iteration (Gortler, Cohen & Slusallek 1993): the patch with the most unshot power
// shoots it to every other patch, over-relaxed (see over_relaxation).
//
// Two sources of the shooter's factors share one loop: the dense form-factor matrix
// (ShootingSolver), or the shooter's own factors computed when it shoots, with nothing stored
// but O(patches) state (shoot_matrix_free, for scenes too large for the matrix).
#pragma once

#include <cstdint>
#include <functional>

#include "solver/solver.h"

namespace radiant {

class Transport;

class ShootingSolver final : public Solver {
public:
    std::string_view name() const override { return "shooting"; }
    SolverOutcome solve(const LinearSystem& system, const SolverControl& control) const override;
};

/// ω (see over_relaxation) from the system's area-weighted mean reflectance.
double shooting_relaxation(const LinearSystem& system);

/// Column `shooter` of F: F(i←shooter) for every receiver i (n values, valid until the next call).
using ShooterColumn = std::function<const float*(std::size_t shooter)>;

/// Where shooting stands, per channel: B = shot + unshot, and (when asked for) `gathered` =
/// F·shot. Empty: nothing shot yet, the unshot light is the source.
struct ShootingState {
    std::array<std::vector<double>, 3> shot, unshot, gathered;
    std::size_t shots = 0;
};

/// The Southwell loop, from `state` on (left where it stopped, so that a later call goes on).
/// `norms` (per channel) bound M = diag(ρ)F for the error estimate; the estimate is refreshed
/// every `check_every` shots. Snapshots show the radiosity with the ambient term, `seen` being
/// each patch's factor sum (empty: a closed scene). With `gather`, F·(shot radiosity) is
/// accumulated in `state.gathered` (the irradiance from reflected light, without a matrix).
SolverOutcome progressive_shooting(const LinearSystem& system,
                                   const std::array<ContractionNorms, 3>& norms,
                                   const ShooterColumn& column, std::size_t check_every,
                                   const std::vector<double>& seen, const SolverControl& control,
                                   ShootingState& state, bool gather = false);

/// Norms of M for a system whose every row of F sums to at most `row_sum` (closed: 1): with
/// reciprocity, column j of diag(A)M sums to A_j Σ_i ρ_i F_ji ≤ A_j ρmax·row_sum, so
/// q_1 ≤ ρmax·row_sum; the max-norm gives no bound (F_ij = F_ji A_j/A_i has no bounded row sum).
/// Its error bound is then the unshot-energy bound U·ρmax/(1 − ρmax) / Σ A B.
ContractionNorms reciprocal_norms(const LinearSystem& system, int channel, double row_sum);

/// Shooting without a form-factor matrix (`system.form_factors` unused): when patch s shoots,
/// its row F(s←i) is computed by `transport` over all patches (in parallel, the same factors as
/// the dense matrix's row s), and reciprocity gives each receiver F(i←s) = F(s←i)·A_s/A_i.
/// Memory O(patches). Rays are added to `rays` as they are cast; `factors` counts the non-zero
/// factors computed; `gathered` receives the reflected irradiance per channel. It ends with a
/// gather sweep (see gather_sweep.h) where that bounds the error closer than the shots' bound.
SolverOutcome shoot_matrix_free(const LinearSystem& system, const Transport& transport,
                                const SolverControl& control, std::uint64_t& rays,
                                std::uint64_t& factors,
                                std::array<std::vector<double>, 3>& gathered);

}  // namespace radiant
