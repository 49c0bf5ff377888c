#include "solver/solver.h"

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

double ambient_term(const std::vector<double>& unshot, const std::vector<double>& reflectance,
                    const std::vector<double>& area) {
    double total_area = 0, rho_area = 0, unshot_area = 0;
    for (std::size_t i = 0; i < area.size(); ++i) {
        total_area += area[i];
        rho_area += reflectance[i] * area[i];
        unshot_area += unshot[i] * area[i];
    }
    if (!(total_area > 0)) return 0;
    const double mean_rho = rho_area / total_area;
    return unshot_area / total_area / (1 - mean_rho);
}

}  // namespace radiant
