#include "solver/gather_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "formfactor/transport.h"

namespace radiant {

GatherSweep gather_sweep(const LinearSystem& s, const Transport& transport,
                         const std::array<std::vector<double>, 3>& radiosity,
                         const SolverControl& control, std::size_t shots, double estimate,
                         double unshot_fraction, std::uint64_t& rays) {
    const std::size_t n = s.n;
    GatherSweep out;
    std::array<double, 3> q_inf{0, 0, 0};
    // Σ_i A_i ρ_i R_ij per source j and channel: the area-weighted L1 norm's columns.
    std::array<std::vector<double>, 3> column;
    for (int c = 0; c < s.channels; ++c) {
        out.gathered[static_cast<std::size_t>(c)].assign(n, 0.0);
        column[static_cast<std::size_t>(c)].assign(n, 0.0);
    }
    std::vector<float> row(n);
    auto last_report = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < n; ++i) {
        if (control.should_stop()) return out;
        transport.form_factor_row(i, row.data(), rays, true);
        double row_sum = 0;
        for (std::size_t j = 0; j < n; ++j) {
            row_sum += row[j];
            out.factors += row[j] > 0 ? 1 : 0;
        }
        for (int c = 0; c < s.channels; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            const std::vector<double>& b = radiosity[ci];
            const double weight = s.area_m2[i] * s.reflectance[ci][i];
            std::vector<double>& col = column[ci];
            double g = 0;
            for (std::size_t j = 0; j < n; ++j) {
                g += row[j] * b[j];
                col[j] += weight * row[j];
            }
            out.gathered[ci][i] = g;
            q_inf[ci] = std::max(q_inf[ci], s.reflectance[ci][i] * row_sum);
        }
        const auto now = std::chrono::steady_clock::now();
        if (control.progress && now - last_report > std::chrono::milliseconds(100)) {
            control.progress(shots, estimate, unshot_fraction);
            last_report = now;
        }
    }
    double total_area = 0;
    for (std::size_t i = 0; i < n; ++i) total_area += s.area_m2[i];
    for (int c = 0; c < s.channels; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        const std::vector<double>& rho = s.reflectance[ci];
        const std::vector<double>& b = radiosity[ci];
        std::vector<double>& next = out.radiosity[ci];
        next.resize(n);
        double r_inf = 0, r_a1 = 0;
        for (std::size_t i = 0; i < n; ++i) {
            next[i] = s.source[ci][i] + rho[i] * out.gathered[ci][i];
            r_inf = std::max(r_inf, std::abs(next[i] - b[i]));
            r_a1 += s.area_m2[i] * std::abs(next[i] - b[i]);
        }
        ContractionNorms q;
        q.q_inf = q_inf[ci];
        for (std::size_t j = 0; j < n; ++j) {
            if (s.area_m2[j] > 0) q.q_1 = std::max(q.q_1, column[ci][j] / s.area_m2[j]);
        }
        // B' − B* = M (B − B*): one more factor q of each norm.
        out.error_bound = std::max(
            out.error_bound, relative_error_bound(q, q.q_inf * r_inf, q.q_1 * r_a1,
                                                  area_weighted_sum(next, s.area_m2), total_area));
    }
    out.complete = true;
    return out;
}

}  // namespace radiant
