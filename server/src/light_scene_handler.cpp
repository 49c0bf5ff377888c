// POST /v1/jobs/{id}/scenes: a light scene from a finished job's stored solution, without
// solving again. Light is linear in the emission: the stored result keeps every group's
// contribution (its `groups`), and a light scene is their sum with the posted dimming. The
// stored result is parsed once per job (StoredSolutions).
#include <memory>

#include "radiant/lighting.h"
#include "radiant/proto/lighting_json.h"
#include "radiant/proto/result_reader.h"
#include "radiant/server/handlers.h"

namespace radiant::server::handlers {

Response post_light_scene(ServiceContext& ctx, const Request& request, const std::string& id) {
    if (auto refused = refuse_json_body(request, ctx.max_body_bytes, "a light scene"))
        return *refused;
    auto posted = proto::parse_light_scene(request.body());
    if (auto* problems = std::get_if<std::vector<Problem>>(&posted)) {
        return error_response(request, http::status::bad_request, "invalid_light_scene", "", "",
                              *problems);
    }
    const auto job = ctx.jobs.find(id);
    if (!job) {
        return error_response(request, http::status::not_found, "not_found",
                              "no job with id \"" + id + "\"");
    }
    if (job->status == JobStatus::queued || job->status == JobStatus::running) {
        return error_response(request, http::status::conflict, "not_ready",
                              "job " + id + " is " + to_string(job->status) +
                                  "; light scenes need its finished solution");
    }
    std::shared_ptr<const Result> solution = ctx.solutions->find(id);
    if (!solution) {
        const auto stored = ctx.store.result(id);
        if (!stored) {
            return error_response(
                request, http::status::not_found, "no_result",
                "job " + id + " was " + to_string(job->status) + " before it produced a result");
        }
        proto::ResultReadOutcome read = proto::read_result(*stored);
        if (!read.ok()) {
            const Problem& p = read.problems.front();
            return error_response(request, http::status::internal_server_error, "internal",
                                  "the stored result of job " + id +
                                      " cannot be read: " + p.pointer + ": " + p.message);
        }
        auto kept = std::make_shared<const Result>(std::move(*read.result));
        ctx.solutions->keep(id, kept);
        solution = std::move(kept);
    }
    if (solution->groups.empty()) {
        return error_response(request, http::status::conflict, "no_groups",
                              "job " + id +
                                  "'s scene names no groups and no light scenes, so "
                                  "its solve kept no group contributions");
    }
    auto evaluated = evaluate_light_scene(*solution, std::get<LightScene>(posted));
    if (auto* problems = std::get_if<std::vector<Problem>>(&evaluated)) {
        return error_response(request, http::status::bad_request, "invalid_light_scene", "", "",
                              *problems);
    }
    return json_response(request, http::status::ok,
                         proto::light_scene_to_json(std::get<LightSceneResult>(evaluated)));
}

}  // namespace radiant::server::handlers
