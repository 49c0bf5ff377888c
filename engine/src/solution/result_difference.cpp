#include "solution/result_difference.h"

#include <algorithm>
#include <cmath>

namespace radiant {
namespace {

double relative(double a, double b, double dark) {
    const double scale = std::max(std::abs(a), dark);
    return scale > 0 ? std::abs(a - b) / scale : 0.0;
}

// The scene's surface area and the values a surface's mean irradiance and radiosity are measured
// against where they are darker: a tenth of their area-weighted means.
struct DarkScales {
    double area_m2 = 0, irradiance = 0, radiosity = 0;
};

DarkScales dark_scales(const Result& r) {
    DarkScales d;
    for (const SurfaceResult& s : r.surfaces) {
        d.area_m2 += s.area_m2;
        d.irradiance += s.area_m2 * s.average_irradiance;
        d.radiosity += s.area_m2 * s.average_radiosity;
    }
    if (d.area_m2 > 0) {
        d.irradiance *= kDarkShare / d.area_m2;
        d.radiosity *= kDarkShare / d.area_m2;
    }
    return d;
}

// What a sensor value (or set) darker than it is measured against: a tenth of the mean of all
// sensor points.
double sensor_dark_scale(const Result& r) {
    double sum = 0;
    std::size_t count = 0;
    for (const SensorResult& s : r.sensors) {
        for (const double e : s.illuminance) sum += e;
        count += s.illuminance.size();
    }
    return count > 0 ? kDarkShare * sum / static_cast<double>(count) : 0;
}

bool sensors_correspond(const Result& a, const std::vector<SensorResult>& b) {
    if (a.sensors.empty() || a.sensors.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.sensors.size(); ++k) {
        if (a.sensors[k].illuminance.size() != b[k].illuminance.size()) return false;
    }
    return true;
}

// Sensor sets: each set's RMS of `difference(set, point)` over the set's mean in `a`, the
// largest.
template <class Difference>
double worst_set_rms(const Result& a, const Difference& difference) {
    const double dark = sensor_dark_scale(a);
    double worst = 0;
    for (std::size_t k = 0; k < a.sensors.size(); ++k) {
        const std::vector<double>& x = a.sensors[k].illuminance;
        if (x.empty()) continue;
        double mean = 0, squares = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            mean += x[i];
            const double d = difference(k, i);
            squares += d * d;
        }
        const double n = static_cast<double>(x.size());
        const double scale = std::max(mean / n, dark);
        if (scale > 0) worst = std::max(worst, std::sqrt(squares / n) / scale);
    }
    return worst;
}

}  // namespace

std::vector<bool> counted_surfaces(const std::vector<double>& areas_m2) {
    double total = 0;
    for (const double a : areas_m2) total += a;
    std::vector<bool> out(areas_m2.size());
    bool any = false;
    for (std::size_t i = 0; i < areas_m2.size(); ++i) {
        out[i] = areas_m2[i] >= kSmallSurfaceShare * total;
        any = any || out[i];
    }
    if (!any) out.assign(areas_m2.size(), true);
    return out;
}

double surface_rms_difference(const Result& a, const Result& b) {
    if (a.surfaces.size() != b.surfaces.size()) return 0;
    const DarkScales dark = dark_scales(a);
    std::vector<double> areas;
    for (const SurfaceResult& s : a.surfaces) areas.push_back(s.area_m2);
    const std::vector<bool> counted = counted_surfaces(areas);
    double squares = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.surfaces.size(); ++i) {
        const SurfaceResult& x = a.surfaces[i];
        const SurfaceResult& y = b.surfaces[i];
        if (!counted[i]) continue;
        const double e = relative(x.average_irradiance, y.average_irradiance, dark.irradiance);
        const double r = relative(x.average_radiosity, y.average_radiosity, dark.radiosity);
        squares += e * e + r * r;
        count += 2;
    }
    return count > 0 ? std::sqrt(squares / static_cast<double>(count)) : 0.0;
}

double sensor_rms_of(const Result& a, const std::vector<SensorResult>& differences) {
    if (!sensors_correspond(a, differences)) return 0;
    return worst_set_rms(
        a, [&](std::size_t k, std::size_t i) { return differences[k].illuminance[i]; });
}

double relative_rms_difference(const Result& a, const Result& b) {
    if (!sensors_correspond(a, b.sensors)) return surface_rms_difference(a, b);
    return worst_set_rms(a, [&](std::size_t k, std::size_t i) {
        return a.sensors[k].illuminance[i] - b.sensors[k].illuminance[i];
    });
}

}  // namespace radiant
