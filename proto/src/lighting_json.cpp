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
