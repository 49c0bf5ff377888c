#include "radiant/proto/lighting_json.h"

#include <algorithm>
#include <cmath>

#include "json_text.h"
#include "radiant/proto/result_json.h"

namespace radiant::proto {
namespace {

using Json = nlohmann::json;

Json vec3_json(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

Json requirement_json(const AppliedRequirement& r) {
    Json out = {{"source", r.source}};
    if (!r.activity.empty()) out["activity"] = r.activity;
    for (const auto& [key, value] :
         {std::pair{"em_lx", r.em_lx}, {"u0", r.u0}, {"ugr_l", r.ugr_l}, {"ra", r.ra}}) {
        if (value) out[key] = *value;
    }
    return out;
}

Json compliance_json(const Compliance& c) {
    Json checks = Json::array();
    for (const Check& k : c.checks) {
        Json check = {{"criterion", k.criterion},
                      {"required", k.required},
                      {"value", k.value},
                      {"status", to_string(k.status)}};
        if (!k.observer.empty()) check["observer"] = k.observer;
        if (!k.note.empty()) check["note"] = k.note;
        checks.push_back(std::move(check));
    }
    return {{"status", to_string(c.status)},
            {"requirement", requirement_json(c.requirement)},
            {"checks", std::move(checks)}};
}

Json observers_json(const std::vector<ObserverResult>& observers) {
    Json out = Json::array();
    for (const ObserverResult& o : observers) {
        Json j = {{"name", o.name},
                  {"position", vec3_json(o.position)},
                  {"view", vec3_json(o.view)},
                  {"standard", o.standard},
                  {"ugr", o.ugr},
                  {"background_luminance", o.background_luminance},
                  {"glare_sum", o.glare_sum},
                  {"ugr_error_estimate", o.ugr_error_estimate}};
        if (o.task) j["task"] = *o.task;
        out.push_back(std::move(j));
    }
    return out;
}

Json groups_json(const std::vector<GroupContribution>& groups) {
    Json out = Json::array();
    for (const GroupContribution& g : groups) {
        Json sensors = Json::array(), observers = Json::array();
        for (const GroupContribution::Sensors& s : g.sensors) {
            Json set = {{"name", s.name}, {"illuminance", s.illuminance}, {"error_lx", s.error_lx}};
            if (!s.initial_illuminance.empty()) set["initial_illuminance"] = s.initial_illuminance;
            sensors.push_back(std::move(set));
        }
        for (const GroupContribution::Glare& o : g.observers) {
            observers.push_back({{"name", o.name},
                                 {"background_luminance", o.background_luminance},
                                 {"background_error", o.background_error},
                                 {"glare_sum", o.glare_sum}});
        }
        Json group = {
            {"name", g.name}, {"sensors", std::move(sensors)}, {"observers", std::move(observers)}};
        if (g.ra) group["ra"] = *g.ra;
        out.push_back(std::move(group));
    }
    return out;
}

Json dimming_json(const std::vector<std::pair<std::string, double>>& dimming) {
    Json out = Json::object();
    for (const auto& [group, value] : dimming) out[group] = value;
    return out;
}

// Readers of a stored result: every value was written by this file, so a mismatch means a
// document from elsewhere; it is reported, never thrown.
struct Reader {
    std::string& error;

    const Json* member(const Json& j, const char* key) {
        if (j.is_object() && j.contains(key)) return &j[key];
        if (error.empty()) error = std::string("the stored result lacks \"") + key + "\"";
        return nullptr;
    }
    double number(const Json& j, const char* key) {
        const Json* x = member(j, key);
        if (x && x->is_number()) return x->get<double>();
        if (error.empty()) error = std::string("\"") + key + "\" is not a number";
        return 0;
    }
    std::string text(const Json& j, const char* key) {
        const Json* x = member(j, key);
        if (x && x->is_string()) return x->get<std::string>();
        if (error.empty()) error = std::string("\"") + key + "\" is not a string";
        return {};
    }
    std::vector<double> numbers(const Json& j, const char* key) {
        std::vector<double> out;
        const Json* x = member(j, key);
        if (!x || !x->is_array()) return out;
        out.reserve(x->size());
        for (const Json& v : *x) out.push_back(v.is_number() ? v.get<double>() : 0.0);
        return out;
    }
    Vec3 vec3(const Json& j, const char* key) {
        const std::vector<double> v = numbers(j, key);
        return v.size() == 3 ? Vec3{v[0], v[1], v[2]} : Vec3{};
    }
    std::optional<double> optional(const Json& j, const char* key) {
        if (j.is_object() && j.contains(key) && j[key].is_number()) return j[key].get<double>();
        return std::nullopt;
    }
};

SensorKind kind_named(const std::string& name) {
    for (const SensorKind k : {SensorKind::planar, SensorKind::vertical, SensorKind::cylindrical,
                               SensorKind::semi_cylindrical}) {
        if (name == to_string(k)) return k;
    }
    return SensorKind::planar;
}

}  // namespace

void add_sensor_design(const SensorResult& s, nlohmann::json& set) {
    set["kind"] = to_string(s.kind);
    set["error_estimate"] = s.error_estimate;
    if (s.initial) {
        set["initial"] = {{"illuminance", s.initial->illuminance},
                          {"min", s.initial->min},
                          {"max", s.initial->max},
                          {"average", s.initial->average},
                          {"u0", s.initial->u0}};
    }
    if (s.surrounding_of) set["surrounding_of"] = *s.surrounding_of;
    if (s.compliance) set["compliance"] = compliance_json(*s.compliance);
}

void add_lighting(const Result& result, nlohmann::json& doc) {
    Json maintenance = Json::array();
    for (const MaintenanceUse& m : result.maintenance) {
        maintenance.push_back({{"factor", m.factor},
                               {"from", m.from},
                               {"luminaires", m.luminaires},
                               {"materials", m.materials}});
    }
    doc["maintenance"] = std::move(maintenance);
    doc["observers"] = observers_json(result.observers);
    if (!result.groups.empty()) doc["groups"] = groups_json(result.groups);
    if (!result.light_scenes.empty()) {
        Json scenes = Json::array();
        for (const LightSceneResult& s : result.light_scenes)
            scenes.push_back(light_scene_to_json(s));
        doc["light_scenes"] = std::move(scenes);
    }
}

nlohmann::json light_scene_to_json(const LightSceneResult& scene) {
    return {{"name", scene.name},
            {"dimming", dimming_json(scene.dimming)},
            {"error_estimate", scene.error_estimate},
            {"sensors", sensors_to_json(scene.sensors)},
            {"observers", observers_json(scene.observers)}};
}

Result lighting_solution_from_json(const nlohmann::json& doc, std::string& error) {
    error.clear();
    Reader read{error};
    Result out;
    if (const Json* sensors = read.member(doc, "sensors"); sensors && sensors->is_array()) {
        for (const Json& s : *sensors) {
            SensorResult r;
            r.name = read.text(s, "name");
            r.illuminance.resize(read.numbers(s, "illuminance").size());
            // Light scenes' sets carry the points as the result's do (older results had none).
            if (s.contains("normal")) r.normal = read.vec3(s, "normal");
            if (s.contains("points") && s["points"].is_array()) {
                for (const Json& point : s["points"]) {
                    const bool xyz = point.is_array() && point.size() == 3 &&
                                     std::all_of(point.begin(), point.end(),
                                                 [](const Json& v) { return v.is_number(); });
                    r.points.push_back(xyz ? Vec3{point[0].get<double>(), point[1].get<double>(),
                                                  point[2].get<double>()}
                                           : Vec3{});
                }
            }
            if (s.contains("kind") && s["kind"].is_string()) r.kind = kind_named(s["kind"]);
            if (s.contains("surrounding_of") && s["surrounding_of"].is_string())
                r.surrounding_of = s["surrounding_of"].get<std::string>();
            if (s.contains("compliance")) {
                const Json* q = read.member(s["compliance"], "requirement");
                if (!q) break;
                Compliance c;
                c.requirement.source = read.text(*q, "source");
                if (q->contains("activity")) c.requirement.activity = read.text(*q, "activity");
                c.requirement.em_lx = read.optional(*q, "em_lx");
                c.requirement.u0 = read.optional(*q, "u0");
                c.requirement.ugr_l = read.optional(*q, "ugr_l");
                c.requirement.ra = read.optional(*q, "ra");
                r.compliance = std::move(c);
            }
            out.sensors.push_back(std::move(r));
        }
    }
    if (const Json* observers = read.member(doc, "observers"); observers && observers->is_array()) {
        for (const Json& o : *observers) {
            ObserverResult r;
            r.name = read.text(o, "name");
            r.position = read.vec3(o, "position");
            r.view = read.vec3(o, "view");
            if (o.contains("task") && o["task"].is_string()) r.task = o["task"].get<std::string>();
            r.standard = o.contains("standard") && o["standard"] == true;
            out.observers.push_back(std::move(r));
        }
    }
    const Json* groups = doc.is_object() && doc.contains("groups") ? &doc["groups"] : nullptr;
    if (groups && groups->is_array()) {
        for (const Json& g : *groups) {
            GroupContribution group;
            group.name = read.text(g, "name");
            group.ra = read.optional(g, "ra");
            const Json* sensors = read.member(g, "sensors");
            const Json* observers = read.member(g, "observers");
            if (!sensors || !observers || !sensors->is_array() || !observers->is_array() ||
                sensors->size() != out.sensors.size() ||
                observers->size() != out.observers.size()) {
                if (error.empty()) error = "group \"" + group.name + "\" does not match the result";
                break;
            }
            for (std::size_t s = 0; s < sensors->size(); ++s) {
                const Json& set = (*sensors)[s];
                GroupContribution::Sensors c;
                c.name = read.text(set, "name");
                c.illuminance = read.numbers(set, "illuminance");
                if (set.contains("initial_illuminance"))
                    c.initial_illuminance = read.numbers(set, "initial_illuminance");
                c.error_lx = read.number(set, "error_lx");
                const std::size_t n = out.sensors[s].illuminance.size();
                if (c.illuminance.size() != n ||
                    (!c.initial_illuminance.empty() && c.initial_illuminance.size() != n)) {
                    if (error.empty())
                        error = "group \"" + group.name + "\" does not match the result";
                }
                group.sensors.push_back(std::move(c));
            }
            for (const Json& o : *observers) {
                group.observers.push_back(
                    {read.text(o, "name"), read.number(o, "background_luminance"),
                     read.number(o, "glare_sum"), read.number(o, "background_error")});
            }
            out.groups.push_back(std::move(group));
        }
    }
    return out;
}

std::variant<LightScene, std::vector<Problem>> parse_light_scene(std::string_view body) {
    std::vector<Problem> problems;
    auto parsed = parse_json_text(body);
    if (auto* refusal = std::get_if<JsonRefusal>(&parsed)) {
        problems.push_back(std::move(refusal->problem));
        return problems;
    }
    const auto& root = std::get<nlohmann::ordered_json>(parsed);
    LightScene scene;
    if (!root.is_object()) {
        problems.push_back({"", "a light scene must be a JSON object"});
        return problems;
    }
    for (const auto& item : root.items()) {
        if (item.key() != "name" && item.key() != "dimming")
            problems.push_back({"/" + item.key(), "unknown key"});
    }
    if (!root.contains("name") || !root["name"].is_string()) {
        problems.push_back({"/name", "name must be a string"});
    } else {
        scene.name = root["name"].get<std::string>();
    }
    if (!root.contains("dimming") || !root["dimming"].is_object()) {
        problems.push_back({"/dimming", "dimming must be an object of group names to numbers"});
    } else {
        for (const auto& item : root["dimming"].items()) {
            const nlohmann::ordered_json::json_pointer p =
                nlohmann::ordered_json::json_pointer("/dimming") / item.key();
            if (!item.value().is_number() || !std::isfinite(item.value().get<double>())) {
                problems.push_back({p.to_string(), "a dimming must be a number in [0, 1]"});
                continue;
            }
            scene.dimming.emplace_back(item.key(), item.value().get<double>());
        }
    }
    if (!problems.empty()) return problems;
    return scene;
}

}  // namespace radiant::proto
