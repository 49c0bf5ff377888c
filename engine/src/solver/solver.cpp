#include "solver/solver.h"

#include <algorithm>

#include "solver/direct_solver.h"
#include "solver/gathering_solvers.h"
#include "solver/shooting_solver.h"

namespace radiant {

std::unique_ptr<Solver> make_solver(std::string_view name) {
    if (name == "direct") return std::make_unique<DirectSolver>();
    if (name == "jacobi") return std::make_unique<JacobiSolver>();
    if (name == "gauss-seidel") return std::make_unique<GaussSeidelSolver>();
    if (name == "shooting") return std::make_unique<ShootingSolver>();
    return nullptr;
}

double area_weighted_sum(const std::vector<double>& values, const std::vector<double>& area) {
    double s = 0;
    for (std::size_t i = 0; i < values.size(); ++i) s += area[i] * values[i];
    return s;
}

double over_relaxation(double mean_reflectance) {
    return std::clamp(1.0 + 0.5 * mean_reflectance, 1.0, 1.5);
}

double ambient_term(const std::vector<double>& unshot, const std::vector<double>& reflectance,
                    const std::vector<double>& area, const std::vector<double>& seen) {
    double seen_area = 0, rho_seen_area = 0, unshot_seen_area = 0;
    for (std::size_t i = 0; i < area.size(); ++i) {
        const double s = seen.empty() ? 1.0 : seen[i];
        seen_area += s * area[i];
        rho_seen_area += s * s * reflectance[i] * area[i];
        unshot_seen_area += s * unshot[i] * area[i];
    }
    if (!(seen_area > 0)) return 0;
    // The share of reflected light that lands on a surface again: ρ̄ in a closed scene.
    const double kept = rho_seen_area / seen_area;
    return kept < 1 ? unshot_seen_area / seen_area / (1 - kept) : 0;
}

}  // namespace radiant
