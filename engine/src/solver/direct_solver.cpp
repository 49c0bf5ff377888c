#include "solver/direct_solver.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace radiant {

SolverOutcome DirectSolver::solve(const LinearSystem& s, const SolverControl& control) const {
    SolverOutcome out;
    const auto n = static_cast<Eigen::Index>(s.n);
    double total_area = 0;
    for (const double a : s.area_m2) total_area += a;
    double worst = 0;
    for (int c = 0; c < s.channels; ++c) {
        const auto& rho = s.reflectance[static_cast<std::size_t>(c)];
        const auto& src = s.source[static_cast<std::size_t>(c)];
        auto& b = out.radiosity[static_cast<std::size_t>(c)];
        Eigen::MatrixXd k(n, n);
        for (Eigen::Index i = 0; i < n; ++i) {
            for (Eigen::Index j = 0; j < n; ++j) {
                k(i, j) = -rho[static_cast<std::size_t>(i)] *
                          s.f(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
            }
            k(i, i) += 1.0;
        }
        Eigen::VectorXd rhs(n);
        for (Eigen::Index i = 0; i < n; ++i) rhs(i) = src[static_cast<std::size_t>(i)];
        const Eigen::VectorXd x = k.partialPivLu().solve(rhs);
        b.assign(x.data(), x.data() + n);
        for (double& v : b) v = std::max(v, 0.0);  // B ≥ 0 exactly; rounding may dip below

        // The bound on what LU's rounding left over, from the explicit residual.
        double r_inf = 0, r_a1 = 0;
        for (std::size_t i = 0; i < s.n; ++i) {
            double g = 0;
            for (std::size_t j = 0; j < s.n; ++j) g += s.f(i, j) * b[j];
            const double r = std::abs(src[i] + rho[i] * g - b[i]);
            r_inf = std::max(r_inf, r);
            r_a1 += s.area_m2[i] * r;
        }
        worst = std::max(worst, relative_error_bound(contraction_norms(s, c), r_inf, r_a1,
                                                     area_weighted_sum(b, s.area_m2), total_area));
    }
    out.iterations = 1;
    out.error_estimate = worst;
    out.converged = worst <= control.tolerance;
    if (control.progress) control.progress(1, worst, 0);
    return out;
}

}  // namespace radiant
