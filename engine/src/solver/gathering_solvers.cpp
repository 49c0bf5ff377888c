#include "solver/gathering_solvers.h"

#include <algorithm>
#include <cmath>

#include "parallel/fork_join.h"

namespace radiant {
namespace {

double total_area(const LinearSystem& s) {
    double a = 0;
    for (const double v : s.area_m2) a += v;
    return a;
}

// One sweep writes new values for every patch and returns (max |Δ|, Σ A|Δ|). After it the
// residual satisfies |r| ≤ M|Δ| elementwise (Jacobi: r = MΔ; Gauss-Seidel: r_i =
// Σ_{j>i} M_ij Δ_j), hence ‖r‖∞ ≤ q_inf ‖Δ‖∞ and ‖r‖_A1 ≤ q_1 ‖Δ‖_A1.
template <typename Sweep>
SolverOutcome iterate(const LinearSystem& s, const SolverControl& control, Sweep sweep) {
    SolverOutcome out;
    const double area = total_area(s);
    std::array<ContractionNorms, 3> q;
    for (int c = 0; c < s.channels; ++c) {
        q[static_cast<std::size_t>(c)] = contraction_norms(s, c);
        out.radiosity[static_cast<std::size_t>(c)] = s.source[static_cast<std::size_t>(c)];
    }
    constexpr std::size_t kMaxSweeps = 1000000;
    auto last_report = std::chrono::steady_clock::now();
    auto last_snapshot = last_report;
    while (out.iterations < kMaxSweeps) {
        double worst = 0;
        for (int c = 0; c < s.channels; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            const auto [d_inf, d_a1] = sweep(ci, out.radiosity[ci]);
            worst = std::max(
                worst, relative_error_bound(q[ci], q[ci].q_inf * d_inf, q[ci].q_1 * d_a1,
                                            area_weighted_sum(out.radiosity[ci], s.area_m2), area));
        }
        ++out.iterations;
        out.error_estimate = worst;
        const auto now = std::chrono::steady_clock::now();
        if (control.progress && now - last_report > std::chrono::milliseconds(100)) {
            control.progress(out.iterations, worst, 0);
            last_report = now;
        }
        if (control.snapshot_due(last_snapshot)) control.snapshot(out.radiosity);
        if (worst <= control.tolerance) {
            out.converged = true;
            break;
        }
        if (control.should_stop()) break;
    }
    return out;
}

}  // namespace

SolverOutcome JacobiSolver::solve(const LinearSystem& s, const SolverControl& control) const {
    std::vector<double> next(s.n), delta(s.n);
    return iterate(s, control, [&](std::size_t c, std::vector<double>& b) {
        const auto& rho = s.reflectance[c];
        const auto& src = s.source[c];
        parallel_for(0, s.n, [&](std::size_t i) {
            double g = 0;
            for (std::size_t j = 0; j < s.n; ++j) g += s.f(i, j) * b[j];
            next[i] = src[i] + rho[i] * g;
            delta[i] = std::abs(next[i] - b[i]);
        });
        b.swap(next);
        double d_inf = 0, d_a1 = 0;
        for (std::size_t i = 0; i < s.n; ++i) {
            d_inf = std::max(d_inf, delta[i]);
            d_a1 += s.area_m2[i] * delta[i];
        }
        return std::pair{d_inf, d_a1};
    });
}

SolverOutcome GaussSeidelSolver::solve(const LinearSystem& s, const SolverControl& control) const {
    return iterate(s, control, [&](std::size_t c, std::vector<double>& b) {
        const auto& rho = s.reflectance[c];
        const auto& src = s.source[c];
        double d_inf = 0, d_a1 = 0;
        for (std::size_t i = 0; i < s.n; ++i) {
            double g = 0;
            for (std::size_t j = 0; j < s.n; ++j) g += s.f(i, j) * b[j];
            const double v = src[i] + rho[i] * g;
            const double d = std::abs(v - b[i]);
            b[i] = v;
            d_inf = std::max(d_inf, d);
            d_a1 += s.area_m2[i] * d;
        }
        return std::pair{d_inf, d_a1};
    });
}

}  // namespace radiant
