// Progressive refinement (Cohen, Chen, Wallace & Greenberg 1988) in its residual form, i.e.
// Southwell iteration (Gortler, Cohen & Slusallek 1993): the patch with the most unshot power
// shoots it to every other patch. Over-relaxation (ω > 1) shoots a little more than is unshot,
// anticipating what the patch will receive back; unshot values may then turn negative.
#pragma once

#include "solver/solver.h"

namespace radiant {

class ShootingSolver final : public Solver {
public:
    std::string_view name() const override { return "shooting"; }
    SolverOutcome solve(const LinearSystem& system, const SolverControl& control) const override;
};

/// ω from the mean reflectance: 1 + ρ̄/2, at most 1.5 (Feda & Purgathofer 1992 report gains
/// growing with reflectivity; larger values oscillate).
double shooting_relaxation(const LinearSystem& system);

}  // namespace radiant
