// The discrete radiosity system B = S + diag(ρ) F B per colour channel, where S is the
// self-emitted exitance plus the reflected first bounce of the point luminaires.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace radiant {

struct LinearSystem {
    std::size_t n = 0;
    int channels = 1;
    const std::vector<float>* form_factors =
        nullptr;  ///< row-major n×n, F[i*n+j]: i receives from j
    std::vector<double> area_m2;
    std::array<std::vector<double>, 3> reflectance;
    std::array<std::vector<double>, 3> source;  ///< S, lm/m²

    float f(std::size_t i, std::size_t j) const { return (*form_factors)[i * n + j]; }
};

/// Operator norms of M = diag(ρ)F for one channel: q_inf = max_i ρ_i Σ_j F_ij (max-norm) and
/// q_1 = max_j Σ_i A_i ρ_i F_ij / A_j (area-weighted L1 norm). Both are < 1 for ρ < 1.
struct ContractionNorms {
    double q_inf = 0;
    double q_1 = 0;
};

ContractionNorms contraction_norms(const LinearSystem& system, int channel);

/// Sound bound on the relative error Σ A|B* − B| / Σ A B, given bounds on the max-norm and the
/// area-weighted L1 norm of the residual r = S + M B − B: since (I − M)⁻¹ ≥ 0 elementwise,
/// Σ A|e| ≤ min(A_tot ‖r‖∞ / (1 − q_inf), ‖r‖_A1 / (1 − q_1)). Returns a huge value when
/// neither norm is a contraction; 0 when B and r are both zero.
double relative_error_bound(const ContractionNorms& q, double r_inf, double r_area_l1,
                            double sum_area_radiosity, double total_area_m2);

}  // namespace radiant
