#include "solution/result_difference.h"

#include <algorithm>
#include <cmath>

namespace radiant {
namespace {

// Values darker than this share of their kind's mean are measured against that share.
constexpr double kDarkShare = 0.1;
// Surfaces smaller than this share of the total area do not count: a chair leg's mean is not
// what the error bar is about, and the hierarchy refines by power, not by surface.
constexpr double kSmallSurfaceShare = 0.01;

double relative(double a, double b, double dark) {
    const double scale = std::max(std::abs(a), dark);
    return scale > 0 ? std::abs(a - b) / scale : 0.0;
}

}  // namespace

double largest_relative_difference(const Result& a, const Result& b) {
    double worst = 0;
    if (a.surfaces.size() == b.surfaces.size()) {
        double area = 0, irradiance = 0, radiosity = 0;
        for (const SurfaceResult& s : a.surfaces) {
            area += s.area_m2;
            irradiance += s.area_m2 * s.average_irradiance;
            radiosity += s.area_m2 * s.average_radiosity;
        }
        const double dark_irradiance = area > 0 ? kDarkShare * irradiance / area : 0;
        const double dark_radiosity = area > 0 ? kDarkShare * radiosity / area : 0;
        for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
            const SurfaceResult& x = a.surfaces[i];
            const SurfaceResult& y = b.surfaces[i];
            if (x.area_m2 < kSmallSurfaceShare * area) continue;
            worst = std::max({worst,
                              relative(x.average_irradiance, y.average_irradiance, dark_irradiance),
                              relative(x.average_radiosity, y.average_radiosity, dark_radiosity)});
        }
    }
    if (a.sensors.size() == b.sensors.size()) {
        double sum = 0;
        std::size_t count = 0;
        for (const SensorResult& s : a.sensors) {
            for (const double e : s.illuminance) sum += e;
            count += s.illuminance.size();
        }
        const double dark = count > 0 ? kDarkShare * sum / static_cast<double>(count) : 0;
        for (std::size_t k = 0; k < a.sensors.size(); ++k) {
            const std::vector<double>& x = a.sensors[k].illuminance;
            const std::vector<double>& y = b.sensors[k].illuminance;
            if (x.size() != y.size()) continue;
            for (std::size_t i = 0; i < x.size(); ++i)
                worst = std::max(worst, relative(x[i], y[i], dark));
        }
    }
    return worst;
}

}  // namespace radiant
