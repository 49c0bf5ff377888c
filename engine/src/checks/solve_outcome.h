// Warnings about how a solve ended, rather than about the scene: a result that is only the best
// so far because the time limit (or another limit) came first, or a solve that overran its time.
#pragma once

#include <vector>

#include "radiant/solve.h"

namespace radiant {

/// time_limit when the solve stopped at its time limit or finished well after it; not_converged
/// when it stopped short of the tolerance for another reason than a cancel.
void check_solve_outcome(const Result& result, const SolveOptions& options, bool cancelled,
                         std::vector<Warning>& out);

}  // namespace radiant
