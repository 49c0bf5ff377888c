#include "radiant/proto/result_reader.h"

#include <array>
#include <cmath>
#include <initializer_list>
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
        if (const auto it = root.find("observers"); it != root.end()) {
            if (!array(*it, Ptr("/observers"))) return std::nullopt;
            for (std::size_t i = 0; i < it->size(); ++i) {
                auto o = observer((*it)[i], Ptr("/observers") / i);
                if (!o) return std::nullopt;
                r.observers.push_back(std::move(*o));
            }
        }
        if (const auto it = root.find("groups"); it != root.end()) {
            if (!array(*it, Ptr("/groups"))) return std::nullopt;
            for (std::size_t i = 0; i < it->size(); ++i) {
                auto g = group((*it)[i], Ptr("/groups") / i, r);
                if (!g) return std::nullopt;
                r.groups.push_back(std::move(*g));
            }
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

    /// `key` of `object` into `out` when present; true when absent.
    bool optional_number(const Json& object, const Ptr& p, const char* key,
                         std::optional<double>& out) {
        const auto it = object.find(key);
        if (it == object.end()) return true;
        double value = 0;
        if (!number(*it, p / key, value)) return false;
        out = value;
        return true;
    }

    bool optional_text(const Json& object, const Ptr& p, const char* key, std::string& out) {
        const auto it = object.find(key);
        return it == object.end() || text(*it, p / key, out);
    }

    bool required_text(const Json& object, const Ptr& p, const char* key, std::string& out) {
        const Json* value = member(object, p, key);
        return value && text(*value, p / key, out);
    }

    bool required_point(const Json& object, const Ptr& p, const char* key, Vec3& out) {
        const Json* value = member(object, p, key);
        return value && point(*value, p / key, out);
    }

    /// The required numbers `fields` of `object`.
    bool required_numbers(const Json& object, const Ptr& p,
                          std::initializer_list<std::pair<const char*, double*>> fields) {
        for (const auto& [key, field] : fields) {
            const Json* value = member(object, p, key);
            if (!value || !number(*value, p / key, *field)) return false;
        }
        return true;
    }

    /// `object` must be a JSON object; `what` names it in the problem.
    bool object(const Json& j, const Ptr& p, const char* what) {
        if (j.is_object()) return true;
        return fail(p, std::string(what) + " must be an object");
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
        if (!sensor_design(j, p, s)) return std::nullopt;
        return s;
    }

    /// The lighting-design members of a set (results before them have none): what light
    /// scenes and the plan's task-area marks read.
    bool sensor_design(const Json& j, const Ptr& p, SensorResult& s) {
        if (const auto it = j.find("kind"); it != j.end()) {
            std::string kind;
            if (!text(*it, p / "kind", kind)) return false;
            const auto known = sensor_kind_named(kind);
            if (!known) return fail(p / "kind", "unknown sensor kind \"" + kind + "\"");
            s.kind = *known;
        }
        if (const auto it = j.find("error_estimate");
            it != j.end() && !number(*it, p / "error_estimate", s.error_estimate)) {
            return false;
        }
        if (const auto it = j.find("surrounding_of"); it != j.end()) {
            if (!text(*it, p / "surrounding_of", s.surrounding_of.emplace())) return false;
        }
        if (const auto it = j.find("compliance"); it != j.end()) {
            s.compliance = compliance(*it, p / "compliance");
            if (!s.compliance) return false;
        }
        return true;
    }

    bool check_status(const Json& j, const Ptr& p, Check::Status& out) {
        std::string name;
        if (!text(j, p, name)) return false;
        const auto status = check_status_named(name);
        if (!status) return fail(p, "unknown status \"" + name + "\"");
        out = *status;
        return true;
    }

    std::optional<Compliance> compliance(const Json& j, const Ptr& p) {
        if (!object(j, p, "compliance")) return std::nullopt;
        Compliance c;
        const Json* status = member(j, p, "status");
        const Json* requirement = status ? member(j, p, "requirement") : nullptr;
        const Json* checks = requirement ? member(j, p, "checks") : nullptr;
        if (!checks || !check_status(*status, p / "status", c.status) ||
            !object(*requirement, p / "requirement", "requirement") ||
            !array(*checks, p / "checks")) {
            return std::nullopt;
        }
        AppliedRequirement& q = c.requirement;
        const Ptr qp = p / "requirement";
        if (!required_text(*requirement, qp, "source", q.source) ||
            !optional_text(*requirement, qp, "activity", q.activity) ||
            !optional_number(*requirement, qp, "em_lx", q.em_lx) ||
            !optional_number(*requirement, qp, "u0", q.u0) ||
            !optional_number(*requirement, qp, "ugr_l", q.ugr_l) ||
            !optional_number(*requirement, qp, "ra", q.ra)) {
            return std::nullopt;
        }
        for (std::size_t i = 0; i < checks->size(); ++i) {
            const Json& k = (*checks)[i];
            const Ptr kp = p / "checks" / i;
            Check check;
            const Json* check_state = nullptr;
            if (!object(k, kp, "a check") || !required_text(k, kp, "criterion", check.criterion) ||
                !(check_state = member(k, kp, "status")) ||
                !check_status(*check_state, kp / "status", check.status) ||
                !required_numbers(k, kp,
                                  {{"required", &check.required}, {"value", &check.value}}) ||
                !optional_text(k, kp, "observer", check.observer) ||
                !optional_text(k, kp, "note", check.note)) {
                return std::nullopt;
            }
            c.checks.push_back(std::move(check));
        }
        return c;
    }

    std::optional<ObserverResult> observer(const Json& j, const Ptr& p) {
        if (!object(j, p, "an observer")) return std::nullopt;
        ObserverResult o;
        if (!required_text(j, p, "name", o.name) || !required_point(j, p, "position", o.position) ||
            !required_point(j, p, "view", o.view)) {
            return std::nullopt;
        }
        if (const auto it = j.find("task"); it != j.end()) {
            if (!text(*it, p / "task", o.task.emplace())) return std::nullopt;
        }
        if (const auto it = j.find("standard"); it != j.end()) {
            if (!it->is_boolean()) {
                fail(p / "standard", "must be true or false");
                return std::nullopt;
            }
            o.standard = it->get<bool>();
        }
        for (const auto& [key, field] :
             {std::pair{"ugr", &o.ugr}, std::pair{"background_luminance", &o.background_luminance},
              std::pair{"glare_sum", &o.glare_sum},
              std::pair{"ugr_error_estimate", &o.ugr_error_estimate}}) {
            if (const auto it = j.find(key); it != j.end() && !number(*it, p / key, *field)) {
                return std::nullopt;
            }
        }
        return o;
    }

    /// A group's contribution: one entry per sensor set and observer of `r`, in their order,
    /// each set with one value per point (light scenes sum them point by point).
    std::optional<GroupContribution> group(const Json& j, const Ptr& p, const Result& r) {
        if (!object(j, p, "a group")) return std::nullopt;
        GroupContribution g;
        if (!required_text(j, p, "name", g.name) || !optional_number(j, p, "ra", g.ra)) {
            return std::nullopt;
        }
        const Json* sensors = member(j, p, "sensors");
        const Json* observers = sensors ? member(j, p, "observers") : nullptr;
        if (!observers || !array(*sensors, p / "sensors") || !array(*observers, p / "observers")) {
            return std::nullopt;
        }
        if (sensors->size() != r.sensors.size()) {
            fail(p / "sensors",
                 "needs one entry per sensor set (" + std::to_string(r.sensors.size()) + ")");
            return std::nullopt;
        }
        if (observers->size() != r.observers.size()) {
            fail(p / "observers",
                 "needs one entry per observer (" + std::to_string(r.observers.size()) + ")");
            return std::nullopt;
        }
        for (std::size_t s = 0; s < sensors->size(); ++s) {
            const Json& set = (*sensors)[s];
            const Ptr sp = p / "sensors" / s;
            GroupContribution::Sensors c;
            const Json* lux = nullptr;
            if (!object(set, sp, "a group's sensor set") ||
                !required_text(set, sp, "name", c.name) ||
                !(lux = member(set, sp, "illuminance")) ||
                !numbers(*lux, sp / "illuminance", c.illuminance) ||
                !required_numbers(set, sp, {{"error_lx", &c.error_lx}})) {
                return std::nullopt;
            }
            if (const auto it = set.find("initial_illuminance");
                it != set.end() &&
                !numbers(*it, sp / "initial_illuminance", c.initial_illuminance)) {
                return std::nullopt;
            }
            // Initial values are kept only where a maintenance factor applies.
            const std::size_t n = r.sensors[s].illuminance.size();
            const char* short_of =
                c.illuminance.size() != n ? "illuminance"
                : !c.initial_illuminance.empty() && c.initial_illuminance.size() != n
                    ? "initial_illuminance"
                    : nullptr;
            if (short_of) {
                fail(sp / short_of, "needs one value per point (" + std::to_string(n) + ")");
                return std::nullopt;
            }
            g.sensors.push_back(std::move(c));
        }
        for (std::size_t o = 0; o < observers->size(); ++o) {
            const Json& glare = (*observers)[o];
            const Ptr op = p / "observers" / o;
            GroupContribution::Glare c;
            if (!object(glare, op, "a group's observer") ||
                !required_text(glare, op, "name", c.name) ||
                !required_numbers(glare, op,
                                  {{"background_luminance", &c.background_luminance},
                                   {"glare_sum", &c.glare_sum},
                                   {"background_error", &c.background_error}})) {
                return std::nullopt;
            }
            g.observers.push_back(std::move(c));
        }
        return g;
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
