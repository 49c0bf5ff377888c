#include "montecarlo/surface_error.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "montecarlo/chi_square_margin.h"
#include "montecarlo/sample_variance.h"
#include "solution/result_difference.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

// The realised error is one draw of the surfaces' noise: its square is a sum of χ² terms,
// one per surface (a surface's irradiance and radiosity are one draw of its photons), and a
// handful of walls, or one dark wall that dominates, leaves few degrees of freedom. The margin
// is chi_square_margin of the terms' effective number (2.6 for one term), but never less than
// this: sixteen batches' spread is itself uncertain, and a solve stops at the first round whose
// estimate meets its target, so rounds that drew a low spread end it. With the quantile alone
// (1.4–1.8 for the meeting room's and the open plan's 10 and 19 surfaces) both were under their
// error at tolerance 0.003 (0.94–0.97 times it; one of six seeds of the meeting room at 0.96, the
// others 1.04–1.8).
constexpr double kMinMargin = 2;

double margin(double degrees) { return std::max(kMinMargin, chi_square_margin(degrees)); }

// Photometric light each surface's front emits per m² in `component` (−1: every one), lm/m².
std::vector<double> emitted_per_area(const PreparedScene& scene, int component) {
    std::vector<double> out(scene.surface_area_m2.size(), 0.0);
    for (const Piece& p : scene.pieces) {
        const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(p.material)];
        if (!m.emits() || (component >= 0 && m.component != component)) continue;
        out[static_cast<std::size_t>(p.surface)] +=
            p.area_m2 * photometric(m.exitance_lm_m2, scene.channels);
    }
    for (std::size_t s = 0; s < out.size(); ++s) {
        out[s] = scene.surface_area_m2[s] > 0 ? out[s] / scene.surface_area_m2[s] : 0;
    }
    return out;
}

struct MeanAndError {
    double mean = 0, error = 0;
};

// A batch-wise quantity's mean and the standard error of that mean.
template <class Batch>
MeanAndError batch_mean(const Batch& batch) {
    std::array<double, PhotonField::kBatches> values{};
    double mean = 0;
    for (int b = 0; b < PhotonField::kBatches; ++b) {
        values[static_cast<std::size_t>(b)] = batch(b);
        mean += values[static_cast<std::size_t>(b)] / PhotonField::kBatches;
    }
    return {mean, std::sqrt(sample_variance_of_mean(values.data(), PhotonField::kBatches))};
}

}  // namespace

MonteCarloError surface_error(const PreparedScene& scene,
                              const std::vector<WeightedField>& fields) {
    MonteCarloError out;
    if (fields.empty()) return out;
    double total_area = 0, total_emitted = 0;
    for (const double a : scene.surface_area_m2) total_area += a;
    double dark_irradiance = 0, dark_radiosity = 0;
    std::vector<std::vector<double>> emitted;
    for (const WeightedField& w : fields) {
        emitted.push_back(emitted_per_area(scene, w.component));
        double flux = 0;
        for (std::size_t s = 0; s < emitted.back().size(); ++s)
            flux += emitted.back()[s] * scene.surface_area_m2[s];
        total_emitted += w.factor * flux;
        dark_irradiance += w.factor * w.field->mean_irradiance();
        dark_radiosity += w.factor * w.field->mean_reflected();
    }
    dark_irradiance *= kDarkShare;
    dark_radiosity =
        kDarkShare * (dark_radiosity + (total_area > 0 ? total_emitted / total_area : 0));
    const std::vector<int>& counted = fields.front().field->counted_surfaces();
    double squares = 0, squares_squared = 0;
    // The quantities with noise: an exact one (an emitter's radiosity before any light returns
    // to it) would dilute the mean square, and the parallel squares' estimate, one noisy value
    // of four, read 0.85 times its error.
    std::size_t noisy = 0;
    for (std::size_t k = 0; k < counted.size(); ++k) {
        const auto s = static_cast<std::size_t>(counted[k]);
        MeanAndError irradiance, radiosity;
        for (std::size_t f = 0; f < fields.size(); ++f) {
            const PhotonField& field = *fields[f].field;
            const double factor = fields[f].factor;
            const MeanAndError h =
                batch_mean([&](int b) { return field.batch_surface_irradiance(k, b); });
            const MeanAndError r =
                batch_mean([&](int b) { return field.batch_surface_reflected(k, b); });
            irradiance.mean += factor * h.mean;
            irradiance.error += factor * h.error;
            radiosity.mean += factor * (emitted[f][s] + r.mean);
            radiosity.error += factor * r.error;
        }
        const auto relative = [](const MeanAndError& x, double dark) {
            const double scale = std::max(x.mean, dark);
            return scale > 0 ? x.error / scale : 0.0;
        };
        const double h = relative(irradiance, dark_irradiance);
        const double b = relative(radiosity, dark_radiosity);
        squares += h * h + b * b;
        squares_squared += (h * h + b * b) * (h * h + b * b);
        noisy += (h > 0 ? 1 : 0) + (b > 0 ? 1 : 0);
    }
    if (counted.empty() || !(squares > 0)) return out;
    const double degrees = squares * squares / squares_squared;
    out.parts.photon_noise = margin(degrees) * std::sqrt(squares / static_cast<double>(noisy));
    out.total = out.parts.photon_noise;
    return out;
}

}  // namespace radiant
