// Dense LU on (I − diag(ρ)F) B = S (Eigen, partial pivoting): the reference for small scenes,
// O(n³) time and 8n² bytes.
#pragma once

#include "solver/solver.h"

namespace radiant {

class DirectSolver final : public Solver {
public:
    std::string_view name() const override { return "direct"; }
    SolverOutcome solve(const LinearSystem& system, const SolverControl& control) const override;
};

}  // namespace radiant
