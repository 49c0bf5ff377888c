// Gathering iterations: every patch collects from all others per sweep. Jacobi uses the previous
// sweep's values (parallel and deterministic); Gauss-Seidel the newest ones (sequential, about
// twice as fast to converge). Both stop on a sound residual bound, never on "the last step was
// small": with ρ = 0.999 a sweep changes B by 0.1 % while the error is still 50 %.
#pragma once

#include "solver/solver.h"

namespace radiant {

class JacobiSolver final : public Solver {
public:
    std::string_view name() const override { return "jacobi"; }
    SolverOutcome solve(const LinearSystem& system, const SolverControl& control) const override;
};

class GaussSeidelSolver final : public Solver {
public:
    std::string_view name() const override { return "gauss-seidel"; }
    SolverOutcome solve(const LinearSystem& system, const SolverControl& control) const override;
};

}  // namespace radiant
