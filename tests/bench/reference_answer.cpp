#include "reference_answer.h"

#include <algorithm>
#include <cmath>

#include "reference_csv_file.h"

namespace radiant::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const SurfaceResult* find_surface(const Result& r, const std::string& name) {
    for (const auto& s : r.surfaces) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

const SensorResult* find_sensor(const Result& r, const std::string& name) {
    for (const auto& s : r.sensors) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

double check_error(const Result& result, const nlohmann::json& check) {
    const std::string what = check.at("what");
    if (what == "surface") {
        const auto* s = find_surface(result, check.at("surface"));
        if (!s) return kNaN;
        const double got = check.at("field") == "average_irradiance" ? s->average_irradiance
                                                                     : s->average_radiosity;
        return std::abs(got / check.at("value").get<double>() - 1.0);
    }
    if (what == "energy") {
        return std::abs(result.stats.absorbed_flux_lm / result.stats.emitted_flux_lm - 1.0);
    }
    if (what == "sensor-max") {
        const auto* dark = find_sensor(result, check.at("sensor"));
        const auto* lit = find_sensor(result, check.at("max_relative_to"));
        if (dark && lit && lit->average > 0) return std::abs(dark->max / lit->average);
    }
    return kNaN;
}

RelativeError summarise(const std::vector<double>& errors) {
    if (errors.empty()) return {};
    double sq = 0, worst = 0;
    for (const double e : errors) {
        if (!std::isfinite(e)) return {};
        sq += e * e;
        worst = std::max(worst, e);
    }
    return {std::sqrt(sq / static_cast<double>(errors.size())), worst};
}

}  // namespace

ReferenceAnswer read_reference_csv(const std::filesystem::path& csv, const std::string& source,
                                   const std::string& sensor) {
    const testing::ReferenceCsv file = testing::read_reference_csv_file(csv);
    ReferenceAnswer out{source, nullptr, sensor, file.illuminance};
    const auto n = static_cast<double>(file.illuminance.size());
    double mean = 0, squares = 0;
    for (const double v : file.illuminance) mean += v / n;
    for (const double e : file.standard_error) squares += e * e / n;
    if (!file.standard_error.empty() && mean > 0) out.error_estimate = std::sqrt(squares) / mean;
    return out;
}

const std::vector<double>& new_lamp_illuminance(const SensorResult& set) {
    return set.initial ? set.initial->illuminance : set.illuminance;
}

double scored_estimate(const Result& result, const ReferenceAnswer& reference) {
    if (reference.checks.is_null()) {
        const auto* set = find_sensor(result, reference.sensor);
        if (set && set->error_estimate > 0) return set->error_estimate;
    }
    return result.stats.error_estimate;
}

RelativeError relative_error(const Result& result, const ReferenceAnswer& reference) {
    std::vector<double> errors;
    if (!reference.checks.is_null()) {
        for (const auto& check : reference.checks) errors.push_back(check_error(result, check));
        return summarise(errors);
    }
    const auto* set = find_sensor(result, reference.sensor);
    const auto& want = reference.illuminance;
    if (!set) return {};
    const std::vector<double>& got = new_lamp_illuminance(*set);
    if (got.size() != want.size() || want.empty()) return {};
    double mean = 0;
    for (const double v : want) mean += v;
    mean /= static_cast<double>(want.size());
    if (!(mean > 0)) return {};
    for (std::size_t i = 0; i < want.size(); ++i) {
        errors.push_back(std::abs(got[i] - want[i]) / mean);
    }
    return summarise(errors);
}

}  // namespace radiant::bench
