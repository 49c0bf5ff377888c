#include <nlohmann/json.hpp>

#include "radiant/proto/result_gltf.h"
#include "radiant/proto/scene_json.h"
#include "radiant/server/handlers.h"

namespace radiant::server::handlers {
namespace {

/// The sensor sets of a stored radiant-result/1 document: names and illuminances only, which is
/// all the glTF's point layer needs.
std::vector<SensorResult> stored_sensors(const std::string& document) {
    std::vector<SensorResult> sensors;
    const auto doc = nlohmann::json::parse(document, nullptr, false);
    if (!doc.is_object() || !doc.contains("sensors") || !doc["sensors"].is_array()) return sensors;
    for (const auto& s : doc["sensors"]) {
        SensorResult r;
        r.name = s.value("name", "");
        if (s.contains("illuminance") && s["illuminance"].is_array()) {
            for (const auto& v : s["illuminance"]) r.illuminance.push_back(v.get<double>());
        }
        sensors.push_back(std::move(r));
    }
    return sensors;
}

}  // namespace

Response get_result_glb(ServiceContext& ctx, const Request& request, const std::string& id) {
    const auto job = ctx.jobs.find(id);
    const auto stored = ctx.store.find(id, true);
    if (!job || !stored) {
        return error_response(request, http::status::not_found, "not_found",
                              "no job with id \"" + id + "\"");
    }
    if (job->status == JobStatus::queued) {
        return error_response(request, http::status::not_found, "not_ready",
                              "job " + id + " is queued; it has no result yet");
    }
    const auto snapshot = ctx.jobs.snapshot(id);
    if (!snapshot) {
        return error_response(
            request, http::status::not_found, "no_result",
            "job " + id + " was " + to_string(job->status) + " before it produced a mesh");
    }
    // The scene was accepted when submitted, so it parses again; it gives the sensor points and
    // the units for the glTF.
    const proto::ParseOutcome scene = proto::parse_scene(stored->scene_json);
    if (!scene.ok()) {
        return error_response(request, http::status::internal_server_error, "internal",
                              "the stored scene of job " + id + " no longer parses");
    }
    Result result;
    result.scene = scene.scene->name;
    result.mesh = expand(snapshot->mesh());
    if (job->status != JobStatus::running) {
        if (auto document = ctx.store.result(id)) result.sensors = stored_sensors(*document);
    }
    return text_response(request, http::status::ok, proto::result_to_glb(result, *scene.scene),
                         "model/gltf-binary");
}

}  // namespace radiant::server::handlers
