#include "radiant/proto/result_json.h"

#include <cmath>
#include <optional>
#include <string>

#include "radiant/proto/lighting_json.h"
#include "radiant/proto/warnings_json.h"

namespace radiant::proto {
namespace {

nlohmann::json stages_json(const std::vector<StageStats>& stages) {
    nlohmann::json out = nlohmann::json::array();
    for (const StageStats& st : stages) {
        out.push_back({{"name", st.name},
                       {"seconds", st.seconds},
                       {"rays", st.rays},
                       {"memory_bytes", st.memory_bytes}});
    }
    return out;
}

nlohmann::json stats_json(const SolveStats& s) {
    const ErrorParts& e = s.error_parts;
    return {{"method", s.method},
            {"patches", s.patches},
            {"elements", s.elements},
            {"links", s.links},
            {"iterations", s.iterations},
            {"rays", s.rays},
            {"seconds", s.seconds},
            {"unshot_fraction", s.unshot_fraction},
            {"error_estimate", s.error_estimate},
            {"emitted_flux_lm", s.emitted_flux_lm},
            {"absorbed_flux_lm", s.absorbed_flux_lm},
            {"channels", s.channels},
            {"threads", s.threads},
            {"error_parts",
             {{"residual", e.residual},
              {"discretisation", e.discretisation},
              {"gather_noise", e.gather_noise},
              {"photon_noise", e.photon_noise},
              {"completion", e.completion}}},
            {"stages", stages_json(s.stages)}};
}

/// Element by element: converting whole integer vectors trips GCC's -Wnull-dereference inside
/// nlohmann's headers (a false positive at -O3).
template <typename Range>
nlohmann::json array_of(const Range& values) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& v : values) out.push_back(v);
    return out;
}

nlohmann::json mesh_json(const SolvedMesh& m) {
    nlohmann::json vertices = nlohmann::json::array();
    for (const Vec3& v : m.vertices) vertices.push_back({v.x, v.y, v.z});
    nlohmann::json triangles = nlohmann::json::array();
    for (const auto& t : m.triangles) triangles.push_back(array_of(t));
    return {{"vertices", std::move(vertices)},
            {"triangles", std::move(triangles)},
            {"triangle_surface", array_of(m.triangle_surface)},
            {"triangle_radiosity", array_of(m.triangle_radiosity)},
            {"vertex_radiosity", array_of(m.vertex_radiosity)}};
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

nlohmann::json vec3_json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json grid_json(const SensorGrid& grid) {
    nlohmann::json points = nlohmann::json::array(), cells = nlohmann::json::array();
    for (const Vec3& x : grid.points) points.push_back(vec3_json(x));
    for (const auto& [iu, iv] : grid.cells) cells.push_back({iu, iv});
    return {{"nu", grid.nu},
            {"nv", grid.nv},
            {"spacing", grid.spacing},
            {"origin", vec3_json(grid.origin)},
            {"u", vec3_json(grid.u)},
            {"v", vec3_json(grid.v)},
            {"points", std::move(points)},
            {"cells", std::move(cells)}};
}

nlohmann::json document(const Result& result, const char* status, const std::string& error) {
    nlohmann::json doc = {
        {"format", "radiant-result/1"}, {"scene", result.scene}, {"status", status}};
    if (!error.empty()) doc["error"] = error;
    return doc;
}

}  // namespace

nlohmann::json sensors_to_json(const std::vector<SensorResult>& sensors) {
    nlohmann::json out = nlohmann::json::array();
    for (const SensorResult& s : sensors) {
        nlohmann::json& set = out.emplace_back(nlohmann::json{{"name", s.name},
                                                              {"illuminance", s.illuminance},
                                                              {"min", s.min},
                                                              {"max", s.max},
                                                              {"average", s.average},
                                                              {"uniformity", s.uniformity},
                                                              {"u0", s.u0},
                                                              {"ud", s.ud}});
        if (s.grid) set["grid"] = grid_json(*s.grid);
        add_sensor_design(s, set);
    }
    return out;
}

nlohmann::json result_to_json(const Result& result) {
    const bool failed = result.status == SolveStatus::failed;
    nlohmann::json doc = document(result, to_string(result.status),
                                  failed && result.error.empty() ? "unknown error" : result.error);
    if (result.status == SolveStatus::stopped && !result.stop_reason.empty())
        doc["stop_reason"] = result.stop_reason;
    doc["stats"] = stats_json(result.stats);
    doc["sensors"] = sensors_to_json(result.sensors);
    nlohmann::json& surfaces = doc["surfaces"] = nlohmann::json::array();
    for (const SurfaceResult& s : result.surfaces) {
        surfaces.push_back({{"name", s.name},
                            {"area", s.area_m2},
                            {"average_irradiance", s.average_irradiance},
                            {"average_radiosity", s.average_radiosity}});
    }
    add_lighting(result, doc);
    doc["warnings"] = warnings_to_json(result.warnings);
    if (result.mesh) doc["mesh"] = mesh_json(*result.mesh);
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
