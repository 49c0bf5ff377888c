#include "solver/shooting_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "formfactor/transport.h"
#include "parallel/fork_join.h"
#include "solver/gather_sweep.h"

namespace radiant {
namespace {

// Matrix-free shooting looks at its unshot light first when its bound is this many tolerances.
constexpr double kFirstStep = 16;
// A gather sweep costs as many rays as a shot of every patch: it is made only once the shots
// have cost as much (so that it at most doubles the time), where the unshot light's signs
// predict a bound this many times closer than the shots', and below this share of the
// tolerance.
constexpr double kWorthwhileCancellation = 1.5;
constexpr double kSweepMargin = 0.8;

// Σ A|u| / |Σ A u| of the unshot light u, the least over the channels: how many times the
// shots' L1 bound exceeds what light of both signs, spread evenly, would leave.
double sign_cancellation(const LinearSystem& s, const ShootingState& state) {
    double least = std::numeric_limits<double>::infinity();
    bool unshot = false;
    for (int c = 0; c < s.channels; ++c) {
        double absolute = 0, sum = 0;
        const std::vector<double>& u = state.unshot[static_cast<std::size_t>(c)];
        for (std::size_t i = 0; i < s.n; ++i) {
            absolute += s.area_m2[i] * std::abs(u[i]);
            sum += s.area_m2[i] * u[i];
        }
        if (absolute > 0) {
            unshot = true;
            least = std::min(least, sum != 0 ? absolute / std::abs(sum) : least);
        }
    }
    return unshot ? least : 1.0;
}

}  // namespace

double shooting_relaxation(const LinearSystem& s) {
    double area = 0, rho_area = 0;
    for (std::size_t i = 0; i < s.n; ++i) {
        double rho = 0;
        for (int c = 0; c < s.channels; ++c)
            rho = std::max(rho, s.reflectance[static_cast<std::size_t>(c)][i]);
        area += s.area_m2[i];
        rho_area += s.area_m2[i] * rho;
    }
    return over_relaxation(area > 0 ? rho_area / area : 0);
}

SolverOutcome progressive_shooting(const LinearSystem& s, const std::array<ContractionNorms, 3>& q,
                                   const ShooterColumn& shooter_column, std::size_t check_every,
                                   const std::vector<double>& seen, const SolverControl& control,
                                   ShootingState& state, bool gather) {
    SolverOutcome out;
    const std::size_t n = s.n;
    const int channels = s.channels;
    const double omega = shooting_relaxation(s);
    check_every = std::max<std::size_t>(1, check_every);

    // Named references, not a structured binding: the estimate's lambda captures them.
    auto& shot = state.shot;
    auto& unshot = state.unshot;
    auto& gathered = state.gathered;
    double total_area = 0, emitted = 0;
    for (std::size_t i = 0; i < n; ++i) total_area += s.area_m2[i];
    for (int c = 0; c < channels; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        if (unshot[ci].size() != n) {
            shot[ci].assign(n, 0.0);
            unshot[ci] = s.source[ci];
            if (gather) gathered[ci].assign(n, 0.0);
        }
        emitted = std::max(emitted, area_weighted_sum(s.source[ci], s.area_m2));
    }
    out.iterations = state.shots;

    // Bound from the residual of B = shot + unshot, which is M·unshot.
    auto estimate = [&](double& unshot_fraction) {
        double worst = 0, unshot_power = 0;
        for (int c = 0; c < channels; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            double u_inf = 0, u_a1 = 0, sum_ab = 0;
            for (std::size_t i = 0; i < n; ++i) {
                u_inf = std::max(u_inf, std::abs(unshot[ci][i]));
                u_a1 += s.area_m2[i] * std::abs(unshot[ci][i]);
                sum_ab += s.area_m2[i] * (shot[ci][i] + unshot[ci][i]);
            }
            unshot_power = std::max(unshot_power, u_a1);
            worst = std::max(worst, relative_error_bound(q[ci], q[ci].q_inf * u_inf,
                                                         q[ci].q_1 * u_a1, sum_ab, total_area));
        }
        unshot_fraction = emitted > 0 ? unshot_power / emitted : 0;
        return worst;
    };

    auto last_report = std::chrono::steady_clock::now();
    auto last_snapshot = last_report;
    // A guard, not a limit that a solvable system meets (the deadline is): the unshot light falls
    // by about ρ per n shots, so a furnace of ρ 0.999 solved to half a percent of the tolerance
    // takes more than 1 000 shots per patch.
    const std::size_t max_shots = 10000 * std::max<std::size_t>(n, 1000);
    while (true) {
        if (out.iterations % check_every == 0) {
            out.error_estimate = estimate(out.unshot_fraction);
            const auto now = std::chrono::steady_clock::now();
            if (control.progress && now - last_report > std::chrono::milliseconds(100)) {
                control.progress(out.iterations, out.error_estimate, out.unshot_fraction);
                last_report = now;
            }
            if (control.snapshot_due(last_snapshot)) {
                std::array<std::vector<double>, 3> b;
                for (int c = 0; c < channels; ++c) {
                    const auto ci = static_cast<std::size_t>(c);
                    const auto& rho = s.reflectance[ci];
                    const double ambient = ambient_term(unshot[ci], rho, s.area_m2, seen);
                    b[ci].resize(n);
                    for (std::size_t i = 0; i < n; ++i) {
                        const double seen_i = seen.empty() ? 1.0 : seen[i];
                        b[ci][i] = shot[ci][i] + unshot[ci][i] + rho[i] * seen_i * ambient;
                    }
                }
                control.snapshot(b);
            }
            if (out.error_estimate <= control.tolerance) {
                out.converged = true;
                break;
            }
            if (control.should_stop() || out.iterations >= max_shots) break;
        }
        // Brightest unshot power first (summed over channels).
        std::size_t shooter = 0;
        double best = -1;
        for (std::size_t i = 0; i < n; ++i) {
            double p = 0;
            for (int c = 0; c < channels; ++c)
                p += std::abs(unshot[static_cast<std::size_t>(c)][i]);
            p *= s.area_m2[i];
            if (p > best) {
                best = p;
                shooter = i;
            }
        }
        if (best <= 0) {
            out.error_estimate = estimate(out.unshot_fraction);
            out.converged = out.error_estimate <= control.tolerance;
            break;
        }
        const float* column = shooter_column(shooter);
        for (int c = 0; c < channels; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            const double delta = omega * unshot[ci][shooter];
            shot[ci][shooter] += delta;
            unshot[ci][shooter] -= delta;
            const auto& rho = s.reflectance[ci];
            auto& u = unshot[ci];
            for (std::size_t i = 0; i < n; ++i) u[i] += rho[i] * column[i] * delta;
            if (gather) {
                auto& g = gathered[ci];
                for (std::size_t i = 0; i < n; ++i) g[i] += column[i] * delta;
            }
        }
        ++out.iterations;
    }
    state.shots = out.iterations;
    for (int c = 0; c < channels; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        out.radiosity[ci].resize(n);
        for (std::size_t i = 0; i < n; ++i)
            out.radiosity[ci][i] = std::max(0.0, shot[ci][i] + unshot[ci][i]);
    }
    return out;
}

SolverOutcome ShootingSolver::solve(const LinearSystem& s, const SolverControl& control) const {
    const std::size_t n = s.n;
    // Columns of F are what a shooter distributes: transpose once for contiguous access.
    std::vector<float> ft(n * n);
    parallel_for(0, n, [&](std::size_t j) {
        for (std::size_t i = 0; i < n; ++i) ft[j * n + i] = s.f(i, j);
    });
    // Row sums weigh the ambient term of snapshots, so only a solve that publishes them needs
    // them (empty: the scene is taken as closed).
    std::vector<double> row_sum;
    if (control.snapshot) {
        row_sum.assign(n, 0.0);
        parallel_for(0, n, [&](std::size_t i) {
            for (std::size_t j = 0; j < n; ++j) row_sum[i] += s.f(i, j);
        });
    }
    std::array<ContractionNorms, 3> q;
    for (int c = 0; c < s.channels; ++c) q[static_cast<std::size_t>(c)] = contraction_norms(s, c);
    // The O(n) estimate is cheap next to a shot's O(n) update only every few shots.
    ShootingState state;
    return progressive_shooting(
        s, q, [&](std::size_t shooter) { return &ft[shooter * n]; }, n / 16, row_sum, control,
        state);
}

ContractionNorms reciprocal_norms(const LinearSystem& s, int channel, double row_sum) {
    double rho_max = 0;
    for (const double rho : s.reflectance[static_cast<std::size_t>(channel)])
        rho_max = std::max(rho_max, rho);
    ContractionNorms q;
    q.q_inf = 1;  // no bound
    q.q_1 = rho_max * row_sum;
    return q;
}

SolverOutcome shoot_matrix_free(const LinearSystem& s, const Transport& transport,
                                const SolverControl& control, std::uint64_t& rays,
                                std::uint64_t& factors,
                                std::array<std::vector<double>, 3>& gathered) {
    const std::size_t n = s.n;
    // Rows of F sum to at most 1 up to rounding (exactly 1 per point for enclosed receivers).
    constexpr double kRowSum = 1.0 + 1e-6;
    std::array<ContractionNorms, 3> q;
    for (int c = 0; c < s.channels; ++c)
        q[static_cast<std::size_t>(c)] = reciprocal_norms(s, c, kRowSum);
    std::vector<float> row(n), column(n);
    auto shooter_column = [&](std::size_t shooter) {
        transport.form_factor_row(shooter, row.data(), rays, true);
        const double a = s.area_m2[shooter];
        parallel_for(0, n, [&](std::size_t i) {
            column[i] = s.area_m2[i] > 0 ? static_cast<float>(row[i] * a / s.area_m2[i]) : 0.0f;
        });
        factors += static_cast<std::uint64_t>(
            std::count_if(row.begin(), row.end(), [](float f) { return f > 0; }));
        return column.data();
    };
    // A shot computes a whole row of factors: the O(n) estimate costs nothing next to it. No
    // row sums are known before every patch has shot: snapshots take the scene as closed.
    // The shots go on in steps of √2 in their bound. After each step, a gather sweep (see
    // gather_sweep.h) where the unshot light's signs predict that it meets the tolerance: its
    // bound is about the shots' over their cancellation (exactly so on a closed sphere), times
    // what the last sweep showed of that prediction.
    ShootingState state;
    double shots_to = kFirstStep * control.tolerance;
    double realised = 1;  // the last sweep's cancellation over the one predicted for it
    while (true) {
        SolverControl shooting = control;
        shooting.tolerance = shots_to;
        SolverOutcome out =
            progressive_shooting(s, q, shooter_column, 1, {}, shooting, state, true);
        const double predicted = realised * sign_cancellation(s, state);
        if (out.converged && state.shots >= s.n && predicted >= kWorthwhileCancellation &&
            out.error_estimate / predicted <= kSweepMargin * control.tolerance) {
            GatherSweep sweep = gather_sweep(s, transport, out.radiosity, control, out.iterations,
                                             out.error_estimate, out.unshot_fraction, rays);
            factors += sweep.factors;
            if (sweep.complete && sweep.error_bound < out.error_estimate &&
                sweep.error_bound <= control.tolerance) {
                out.radiosity = std::move(sweep.radiosity);
                gathered = std::move(sweep.gathered);
                out.error_estimate = sweep.error_bound;
                return out;
            }
            if (!sweep.complete) out.converged = false;
            if (sweep.error_bound > 0)
                realised *= out.error_estimate / sweep.error_bound / predicted;
        }
        // Stopped (deadline, cancellation) or met: the shots' radiosity, bound and light stand.
        if (!out.converged || out.error_estimate <= control.tolerance) {
            out.converged = out.converged && out.error_estimate <= control.tolerance;
            gathered = std::move(state.gathered);
            return out;
        }
        shots_to = std::max(control.tolerance, out.error_estimate / std::sqrt(2.0));
    }
}

}  // namespace radiant
