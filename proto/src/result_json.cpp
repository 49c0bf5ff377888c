#include "radiant/proto/result_json.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "radiant/proto/lighting_json.h"
#include "radiant/proto/warnings_json.h"

namespace radiant::proto {
namespace {

/// Rounds as section "Digits" of docs/scene-format.md says: values to `digits` significant
/// digits, error estimates up to kEstimateDigits, lengths to micrometres, counts exact.
class Rounding {
public:
    explicit Rounding(int digits) : digits_(std::clamp(digits, 1, kMaxDigits)) {}

    double value(double v) const { return round_significant(v, digits_); }
    double estimate(double v) const {
        return round_up_significant(v, std::min(digits_, kEstimateDigits));
    }
    double length(double v) const { return round_decimals(v, kLengthDecimals); }
    nlohmann::json point(const Vec3& p) const {
        return nlohmann::json::array({length(p.x), length(p.y), length(p.z)});
    }
    nlohmann::json values(const std::vector<double>& vs) const {
        nlohmann::json out = nlohmann::json::array();
        for (const double v : vs) out.push_back(value(v));
        return out;
    }
    nlohmann::json points(const std::vector<Vec3>& ps) const {
        nlohmann::json out = nlohmann::json::array();
        for (const Vec3& p : ps) out.push_back(point(p));
        return out;
    }

private:
    int digits_;
};

nlohmann::json stages_json(const std::vector<StageStats>& stages, const Rounding& round) {
    nlohmann::json out = nlohmann::json::array();
    for (const StageStats& st : stages) {
        out.push_back({{"name", st.name},
                       {"seconds", round.value(st.seconds)},
                       {"rays", st.rays},
                       {"memory_bytes", st.memory_bytes}});
    }
    return out;
}

nlohmann::json stats_json(const SolveStats& s, const Rounding& round) {
    const ErrorParts& e = s.error_parts;
    return {{"method", s.method},
            {"patches", s.patches},
            {"elements", s.elements},
            {"links", s.links},
            {"iterations", s.iterations},
            {"rays", s.rays},
            {"seconds", round.value(s.seconds)},
            {"unshot_fraction", round.estimate(s.unshot_fraction)},
            {"error_estimate", round.estimate(s.error_estimate)},
            {"emitted_flux_lm", round.value(s.emitted_flux_lm)},
            {"absorbed_flux_lm", round.value(s.absorbed_flux_lm)},
            {"channels", s.channels},
            {"threads", s.threads},
            {"error_parts",
             {{"residual", round.estimate(e.residual)},
              {"discretisation", round.estimate(e.discretisation)},
              {"gather_noise", round.estimate(e.gather_noise)},
              {"photon_noise", round.estimate(e.photon_noise)},
              {"completion", round.estimate(e.completion)},
              {"cross_check", round.estimate(e.cross_check)}}},
            {"stages", stages_json(s.stages, round)}};
}

/// Element by element: converting whole integer vectors trips GCC's -Wnull-dereference inside
/// nlohmann's headers (a false positive at -O3).
template <typename Range>
nlohmann::json array_of(const Range& values) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& v : values) out.push_back(v);
    return out;
}

nlohmann::json mesh_json(const SolvedMesh& m, const Rounding& round) {
    nlohmann::json triangles = nlohmann::json::array();
    for (const auto& t : m.triangles) triangles.push_back(array_of(t));
    return {{"vertices", round.points(m.vertices)},
            {"triangles", std::move(triangles)},
            {"triangle_surface", array_of(m.triangle_surface)},
            {"triangle_radiosity", round.values(m.triangle_radiosity)},
            {"vertex_radiosity", round.values(m.vertex_radiosity)}};
}

/// Pointer of the first non-finite number in `j`, if any (nlohmann would write it as null).
std::optional<std::string> non_finite(const nlohmann::json& j,
                                      const nlohmann::json::json_pointer& p) {
    if (j.is_number_float() && !std::isfinite(j.get<double>())) return p.to_string();
    if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) {
            if (auto bad = non_finite(j[i], p / i)) return bad;
        }
    } else if (j.is_object()) {
        for (const auto& item : j.items()) {
            if (auto bad = non_finite(item.value(), p / item.key())) return bad;
        }
    }
    return std::nullopt;
}

nlohmann::json grid_json(const SensorGrid& grid, const Rounding& round) {
    nlohmann::json cells = nlohmann::json::array();
    for (const auto& [iu, iv] : grid.cells) cells.push_back({iu, iv});
    return {{"nu", grid.nu},
            {"nv", grid.nv},
            {"spacing", round.length(grid.spacing)},
            {"origin", round.point(grid.origin)},
            {"u", round.point(grid.u)},
            {"v", round.point(grid.v)},
            {"points", round.points(grid.points)},
            {"cells", std::move(cells)}};
}

nlohmann::json document(const Result& result, const char* status, const std::string& error) {
    nlohmann::json doc = {{"format", "radiant-result/1"},
                          {"scene", result.scene},
                          {"status", status},
                          {"units", result_units_json()}};
    if (!error.empty()) doc["error"] = error;
    return doc;
}

}  // namespace

nlohmann::json result_units_json() {
    return {{"length", "m"},       {"area", "m²"}, {"illuminance", "lx"},
            {"exitance", "lm/m²"}, {"flux", "lm"}, {"time", "s"}};
}

nlohmann::json sensors_to_json(const std::vector<SensorResult>& sensors, int digits) {
    const Rounding round(digits);
    nlohmann::json out = nlohmann::json::array();
    for (const SensorResult& s : sensors) {
        nlohmann::json& set =
            out.emplace_back(nlohmann::json{{"name", s.name},
                                            {"normal", round.point(s.normal)},
                                            {"points", round.points(s.points)},
                                            {"illuminance", round.values(s.illuminance)},
                                            {"min", round.value(s.min)},
                                            {"max", round.value(s.max)},
                                            {"average", round.value(s.average)},
                                            {"uniformity", round.value(s.uniformity)},
                                            {"u0", round.value(s.u0)},
                                            {"ud", round.value(s.ud)}});
        if (s.grid) set["grid"] = grid_json(*s.grid, round);
        add_sensor_design(s, set);
    }
    return out;
}

nlohmann::json result_to_json(const Result& result, int digits) {
    const Rounding round(digits);
    const bool failed = result.status == SolveStatus::failed;
    nlohmann::json doc = document(result, to_string(result.status),
                                  failed && result.error.empty() ? "unknown error" : result.error);
    if (result.status == SolveStatus::stopped && !result.stop_reason.empty())
        doc["stop_reason"] = result.stop_reason;
    doc["stats"] = stats_json(result.stats, round);
    doc["sensors"] = sensors_to_json(result.sensors, digits);
    nlohmann::json& surfaces = doc["surfaces"] = nlohmann::json::array();
    for (const SurfaceResult& s : result.surfaces) {
        surfaces.push_back({{"name", s.name},
                            {"area", round.value(s.area_m2)},
                            {"average_irradiance", round.value(s.average_irradiance)},
                            {"average_radiosity", round.value(s.average_radiosity)}});
    }
    add_lighting(result, doc);
    doc["warnings"] = warnings_to_json(result.warnings);
    if (result.mesh) doc["mesh"] = mesh_json(*result.mesh, round);
    if (const auto bad = non_finite(doc, nlohmann::json::json_pointer())) {
        nlohmann::json failed_doc = document(
            result, "failed", "internal error: the solver produced a non-finite value at " + *bad);
        failed_doc["stats"] = nlohmann::json::object();
        failed_doc["sensors"] = nlohmann::json::array();
        failed_doc["surfaces"] = nlohmann::json::array();
        failed_doc["warnings"] = warnings_to_json(result.warnings);
        return failed_doc;
    }
    return doc;
}

}  // namespace radiant::proto
