#include "solver/linear_system.h"

#include <algorithm>
#include <limits>

namespace radiant {

ContractionNorms contraction_norms(const LinearSystem& s, int channel) {
    ContractionNorms q;
    const auto& rho = s.reflectance[static_cast<std::size_t>(channel)];
    std::vector<double> column(s.n, 0.0);
    for (std::size_t i = 0; i < s.n; ++i) {
        double row = 0;
        for (std::size_t j = 0; j < s.n; ++j) {
            const double f = s.f(i, j);
            row += f;
            column[j] += s.area_m2[i] * rho[i] * f;
        }
        q.q_inf = std::max(q.q_inf, rho[i] * row);
    }
    for (std::size_t j = 0; j < s.n; ++j) {
        if (s.area_m2[j] > 0) q.q_1 = std::max(q.q_1, column[j] / s.area_m2[j]);
    }
    return q;
}

double relative_error_bound(const ContractionNorms& q, double r_inf, double r_area_l1,
                            double sum_area_radiosity, double total_area_m2) {
    constexpr double kUnknown = 1e30;  // neither norm contracts: no bound can be given
    if (r_inf == 0 && r_area_l1 == 0) return 0;
    if (!(q.q_inf < 1) && !(q.q_1 < 1)) return kUnknown;
    if (!(sum_area_radiosity > 0)) return kUnknown;
    double bound = std::numeric_limits<double>::infinity();
    if (q.q_inf < 1) bound = std::min(bound, total_area_m2 * r_inf / (1 - q.q_inf));
    if (q.q_1 < 1) bound = std::min(bound, r_area_l1 / (1 - q.q_1));
    return std::min(kUnknown, bound / sum_area_radiosity);
}

}  // namespace radiant
