#include "radiant/proto/result_reader.h"

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <variant>

#include "json_text.h"

namespace radiant::proto {
namespace {

using Json = nlohmann::ordered_json;
using Ptr = Json::json_pointer;

/// Reads one document; the first problem ends the reading (a damaged result is refused whole).
class ResultReader {
public:
    std::optional<Result> read(const Json& root) {
        Result r;
        if (!root.is_object()) {
            fail(Ptr(), "a result must be a JSON object");
            return std::nullopt;
        }
        const Json* format = member(root, Ptr(), "format");
        if (format && *format != "radiant-result/1") {
            fail(Ptr("/format"), "format must be \"radiant-result/1\"");
            return std::nullopt;
        }
        const Json* scene = format ? member(root, Ptr(), "scene") : nullptr;
        if (!scene || !text(*scene, Ptr("/scene"), r.scene) || !read_status(root, r)) {
            return std::nullopt;
        }
        const Json* sensors = member(root, Ptr(), "sensors");
        if (!sensors || !array(*sensors, Ptr("/sensors"))) return std::nullopt;
        for (std::size_t i = 0; i < sensors->size(); ++i) {
            auto set = sensor_set((*sensors)[i], Ptr("/sensors") / i);
            if (!set) return std::nullopt;
            r.sensors.push_back(std::move(*set));
        }
        const Json* surfaces = member(root, Ptr(), "surfaces");
        if (!surfaces || !array(*surfaces, Ptr("/surfaces"))) return std::nullopt;
        for (std::size_t i = 0; i < surfaces->size(); ++i) {
            auto surface = surface_result((*surfaces)[i], Ptr("/surfaces") / i);
            if (!surface) return std::nullopt;
            r.surfaces.push_back(std::move(*surface));
        }
        if (const auto it = root.find("mesh"); it != root.end()) {
            r.mesh = mesh(*it, Ptr("/mesh"), r.surfaces.size());
            if (!r.mesh) return std::nullopt;
        }
        return r;
    }

    std::vector<Problem> problems;

private:
    /// Records the problem; false, so that readers can `return fail(...)`.
    bool fail(const Ptr& p, std::string message) {
        problems.push_back({p.to_string(), std::move(message)});
        return false;
    }

    const Json* member(const Json& object, const Ptr& p, const char* key) {
        const auto it = object.find(key);
        if (it != object.end()) return &*it;
        fail(p / key, std::string("missing required key \"") + key + "\"");
        return nullptr;
    }

    bool array(const Json& j, const Ptr& p) {
        if (j.is_array()) return true;
        fail(p, "must be an array");
        return false;
    }

    bool text(const Json& j, const Ptr& p, std::string& out) {
        if (!j.is_string()) return fail(p, "must be a string");
        out = j.get<std::string>();
        return true;
    }

    bool number(const Json& j, const Ptr& p, double& out) {
        if (!j.is_number() || !std::isfinite(j.get<double>())) {
            return fail(p, "must be a finite number");
        }
        out = j.get<double>();
        return true;
    }

    bool numbers(const Json& j, const Ptr& p, std::vector<double>& out) {
        if (!array(j, p)) return false;
        out.resize(j.size());
        for (std::size_t i = 0; i < j.size(); ++i) {
            if (!number(j[i], p / i, out[i])) return false;
        }
        return true;
    }

    bool point(const Json& j, const Ptr& p, Vec3& out) {
        if (!j.is_array() || j.size() != 3) return fail(p, "must be an array of 3 numbers");
        return number(j[0], p / 0, out.x) && number(j[1], p / 1, out.y) &&
               number(j[2], p / 2, out.z);
    }

    bool points(const Json& j, const Ptr& p, std::vector<Vec3>& out) {
        if (!array(j, p)) return false;
        out.resize(j.size());
        for (std::size_t i = 0; i < j.size(); ++i) {
            if (!point(j[i], p / i, out[i])) return false;
        }
        return true;
    }

    /// An integer index in [0, size).
    bool index(const Json& j, const Ptr& p, std::size_t size, int& out) {
        if (!j.is_number_integer() || j.get<long long>() < 0 ||
            j.get<long long>() >= static_cast<long long>(size)) {
            return fail(p, "must be an index below " + std::to_string(size));
        }
        out = static_cast<int>(j.get<long long>());
        return true;
    }

    bool read_status(const Json& root, Result& r) {
        std::string status;
        const Json* s = member(root, Ptr(), "status");
        if (!s || !text(*s, Ptr("/status"), status)) return false;
        if (status == "converged") {
            r.status = SolveStatus::converged;
        } else if (status == "stopped" || status == "running") {
            r.status = SolveStatus::stopped;
        } else if (status == "failed") {
            r.status = SolveStatus::failed;
            if (const auto it = root.find("error"); it != root.end() && it->is_string()) {
                r.error = it->get<std::string>();
            }
        } else {
            return fail(Ptr("/status"), "unknown status \"" + status + "\"");
        }
        return true;
    }

    std::optional<SensorResult> sensor_set(const Json& j, const Ptr& p) {
        if (!j.is_object()) {
            fail(p, "a sensor set must be an object");
            return std::nullopt;
        }
        SensorResult s;
        const Json* name = member(j, p, "name");
        const Json* lux = name ? member(j, p, "illuminance") : nullptr;
        if (!lux || !text(*name, p / "name", s.name) ||
            !numbers(*lux, p / "illuminance", s.illuminance)) {
            return std::nullopt;
        }
        for (const auto& [key, field] :
             {std::pair{"min", &s.min}, std::pair{"max", &s.max}, std::pair{"average", &s.average},
              std::pair{"uniformity", &s.uniformity}, std::pair{"u0", &s.u0},
              std::pair{"ud", &s.ud}}) {
            if (const auto it = j.find(key); it != j.end() && !number(*it, p / key, *field)) {
                return std::nullopt;
            }
        }
        // Results written before sets carried their points have none: such a set reads with
        // its values only (pictures and CSV then say what is missing).
        if (const auto it = j.find("points"); it != j.end()) {
            if (!points(*it, p / "points", s.points)) return std::nullopt;
            if (s.points.size() != s.illuminance.size()) {
                fail(p / "points", "has " + std::to_string(s.points.size()) + " points for " +
                                       std::to_string(s.illuminance.size()) + " values");
                return std::nullopt;
            }
        }
        if (const auto it = j.find("normal");
            it != j.end() && !point(*it, p / "normal", s.normal)) {
            return std::nullopt;
        }
        return s;
    }

    std::optional<SurfaceResult> surface_result(const Json& j, const Ptr& p) {
        if (!j.is_object()) {
            fail(p, "a surface must be an object");
            return std::nullopt;
        }
        SurfaceResult s;
        const Json* name = member(j, p, "name");
        if (!name || !text(*name, p / "name", s.name)) return std::nullopt;
        for (const auto& [key, field] :
             {std::pair{"area", &s.area_m2}, std::pair{"average_irradiance", &s.average_irradiance},
              std::pair{"average_radiosity", &s.average_radiosity}}) {
            const Json* value = member(j, p, key);
            if (!value || !number(*value, p / key, *field)) return std::nullopt;
        }
        return s;
    }

    std::optional<SolvedMesh> mesh(const Json& j, const Ptr& p, std::size_t surfaces) {
        if (!j.is_object()) {
            fail(p, "the mesh must be an object");
            return std::nullopt;
        }
        SolvedMesh m;
        const Json* vertices = member(j, p, "vertices");
        if (!vertices || !points(*vertices, p / "vertices", m.vertices)) return std::nullopt;
        const Json* triangles = member(j, p, "triangles");
        if (!triangles || !array(*triangles, p / "triangles")) return std::nullopt;
        for (std::size_t t = 0; t < triangles->size(); ++t) {
            const Json& tri = (*triangles)[t];
            const Ptr tp = p / "triangles" / t;
            if (!tri.is_array() || tri.size() != 3) {
                fail(tp, "must be 3 vertex indices");
                return std::nullopt;
            }
            std::array<int, 3> corners{};
            for (std::size_t k = 0; k < 3; ++k) {
                if (!index(tri[k], tp / k, m.vertices.size(), corners[k])) return std::nullopt;
            }
            m.triangles.push_back(corners);
        }
        const Json* owner = member(j, p, "triangle_surface");
        if (!owner || !array(*owner, p / "triangle_surface")) return std::nullopt;
        m.triangle_surface.resize(owner->size());
        for (std::size_t t = 0; t < owner->size(); ++t) {
            if (!index((*owner)[t], p / "triangle_surface" / t, surfaces, m.triangle_surface[t])) {
                return std::nullopt;
            }
        }
        const Json* flat = member(j, p, "triangle_radiosity");
        const Json* smooth = flat ? member(j, p, "vertex_radiosity") : nullptr;
        if (!smooth || !numbers(*flat, p / "triangle_radiosity", m.triangle_radiosity) ||
            !numbers(*smooth, p / "vertex_radiosity", m.vertex_radiosity)) {
            return std::nullopt;
        }
        const std::size_t n = m.triangles.size();
        if (m.triangle_surface.size() != n || m.triangle_radiosity.size() != n) {
            fail(p, "triangle_surface and triangle_radiosity need one value per triangle");
            return std::nullopt;
        }
        if (m.vertex_radiosity.size() != m.vertices.size()) {
            fail(p / "vertex_radiosity", "needs one value per vertex");
            return std::nullopt;
        }
        return m;
    }
};

}  // namespace

ResultReadOutcome read_result(std::string_view json_text) {
    ResultReadOutcome out;
    auto parsed = parse_json_text(json_text);
    if (auto* refusal = std::get_if<JsonRefusal>(&parsed)) {
        out.problems.push_back(std::move(refusal->problem));
        return out;
    }
    ResultReader reader;
    out.result = reader.read(std::get<Json>(parsed));
    out.problems = std::move(reader.problems);
    if (!out.problems.empty()) out.result.reset();
    return out;
}

}  // namespace radiant::proto
