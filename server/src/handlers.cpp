#include "radiant/server/handlers.h"

#include <algorithm>
#include <charconv>
#include <string_view>
#include <vector>

#include "embedded_files.h"
#include "job_errors.h"
#include "radiant/proto/result_gltf.h"
#include "radiant/proto/result_json.h"
#include "radiant/proto/scene_json.h"
#include "radiant/proto/warnings_json.h"
#include "radiant/warnings.h"

namespace radiant::server::handlers {
namespace {

/// A page bigger than this is refused: one request must stay cheap for the store and the client.
constexpr std::size_t kMaxPageSize = 1000;
constexpr std::size_t kDefaultPageSize = 50;
/// How long a client should wait before retrying a full queue; solves take seconds to minutes.
constexpr const char* kRetryAfterSeconds = "5";

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

Response job_response(const Request& request, http::status status, const JobRecord& job) {
    Response response = json_response(request, status, job_to_json(job));
    response.set(http::field::location, "/v1/jobs/" + job.id);
    return response;
}

/// The latest state of a running job as a radiant-result/1 document: statistics so far, its
/// progress, and the sensor values of its latest snapshot that had some (surface averages are
/// computed only at the end of a solve).
nlohmann::json running_result(ServiceContext& ctx, const JobRecord& job,
                              const JobSnapshot* snapshot) {
    const JobProgress& p = job.progress;
    const RunningScene scene = ctx.jobs.running_scene(job.id);
    nlohmann::json doc = {{"format", "radiant-result/1"},
                          {"scene", scene.name},
                          {"status", "running"},
                          {"units", proto::result_units_json()},
                          {"stats",
                           {{"iterations", p.iterations},
                            {"rays", p.rays},
                            {"seconds", proto::round_significant(p.elapsed_seconds, scene.digits)},
                            {"unshot_fraction", proto::round_up_significant(
                                                    p.unshot_fraction, proto::kEstimateDigits)}}},
                          {"progress", job_progress_json(p)},
                          {"sensors", nlohmann::json::array()},
                          {"surfaces", nlohmann::json::array()},
                          {"warnings", job.warnings}};
    if (p.error_estimate) {
        doc["stats"]["error_estimate"] =
            proto::round_up_significant(*p.error_estimate, proto::kEstimateDigits);
    }
    if (snapshot) {
        doc["snapshot"] = {{"version", snapshot->info().version},
                           {"mesh_version", snapshot->info().mesh_version}};
        if (snapshot->info().sensors)
            doc["sensors"] = proto::sensors_to_json(*snapshot->info().sensors, scene.digits);
    }
    return doc;
}

/// `document` (a JSON object's text) with a "mesh" member: contract §3's solved mesh.
std::string add_mesh(std::string document, const CompactMesh& mesh) {
    while (!document.empty() && document.back() != '}') document.pop_back();
    if (document.empty()) return document;
    document.pop_back();
    return document + ",\"mesh\":{" + geometry_json(mesh) + "," + radiosity_json(mesh) + "}}";
}

/// Warnings as the problems of a refusal: "message [code]" at the warning's pointer.
std::vector<Problem> strict_problems(const std::vector<Warning>& warnings) {
    std::vector<Problem> problems;
    for (const Warning& w : warnings) problems.push_back({w.pointer, proto::message_with_code(w)});
    return problems;
}

/// The OpenAPI's Idempotency-Key: at most 200 characters, visible ASCII or spaces, as every
/// store indexes it alike (PostgreSQL refuses text that is not UTF-8, and long index rows).
bool valid_idempotency_key(std::string_view key) {
    return key.size() <= 200 &&
           std::all_of(key.begin(), key.end(), [](char c) { return c >= 0x20 && c < 0x7f; });
}

}  // namespace

Response submit_job(ServiceContext& ctx, const Request& request) {
    const std::string& body = request.body();
    if (auto refused = refuse_json_body(request, ctx.max_body_bytes, "a scene")) return *refused;
    const std::string key(request["Idempotency-Key"]);
    if (!valid_idempotency_key(key)) {
        return error_response(request, http::status::bad_request, "bad_request",
                              "Idempotency-Key must be at most 200 visible ASCII characters");
    }
    proto::ParseLimits limits;
    limits.max_bytes = ctx.max_body_bytes;
    // One pass: JSON syntax and budget, then the scene.
    const proto::ParseOutcome outcome = proto::parse_scene(body, limits);
    switch (outcome.refusal) {
        case proto::Refusal::none:
            break;
        case proto::Refusal::not_json:
            return error_response(request, http::status::bad_request, "invalid_json", "", "",
                                  outcome.problems);
        case proto::Refusal::over_budget:
            return error_response(request, http::status::payload_too_large, "too_complex", "", "",
                                  outcome.problems);
        case proto::Refusal::scene:
            return error_response(request, http::status::bad_request, "invalid_scene", "", "",
                                  outcome.problems);
    }
    // A strict scene is refused with its warnings before it is queued. The checks build a ray
    // tracer over the scene: only strict scenes pay that here (docs/warnings.md).
    if (outcome.scene->settings.strict) {
        if (const std::vector<Problem> warned = strict_problems(check_modelling(*outcome.scene));
            !warned.empty()) {
            return error_response(request, http::status::bad_request, "strict_warnings", "", "",
                                  warned);
        }
    }
    const SubmitOutcome submitted = ctx.jobs.submit(body, key);
    switch (submitted.kind) {
        case SubmitOutcome::Kind::accepted:
        case SubmitOutcome::Kind::replayed: {
            Response response = json_response(
                request, http::status::accepted,
                {{"id", submitted.job.id}, {"status", to_string(submitted.job.status)}});
            response.set(http::field::location, "/v1/jobs/" + submitted.job.id);
            return response;
        }
        case SubmitOutcome::Kind::queue_full: {
            Response response = error_response(request, http::status::too_many_requests,
                                               "queue_full", "the job queue is full; retry later");
            response.set(http::field::retry_after, kRetryAfterSeconds);
            return response;
        }
        case SubmitOutcome::Kind::store_unwritable: {
            Response response =
                error_response(request, http::status::service_unavailable, "store_unwritable",
                               "the job store cannot take the job: " + submitted.reason);
            response.set(http::field::retry_after, kRetryAfterSeconds);
            return response;
        }
        case SubmitOutcome::Kind::shutting_down:
            break;
    }
    return error_response(request, http::status::service_unavailable, "shutting_down",
                          "the service is shutting down");
}

Response get_job(ServiceContext& ctx, const Request& request, const std::string& id) {
    const auto job = ctx.jobs.find(id);
    if (!job) return unknown_job(request, id);
    return job_response(request, http::status::ok, *job);
}

Response get_result(ServiceContext& ctx, const Request& request, const std::string& id,
                    const Query& query) {
    bool with_mesh = false;
    if (const auto it = query.find("include"); it != query.end()) {
        if (it->second != "mesh") {
            return error_response(request, http::status::bad_request, "invalid_query",
                                  "include must be \"mesh\", not \"" + it->second + "\"");
        }
        with_mesh = true;
    }
    const auto job = ctx.jobs.find(id);
    if (!job) return unknown_job(request, id);
    if (job->status == JobStatus::queued) return not_ready(request, id);
    // One snapshot for the whole answer, so its version and its mesh agree.
    const bool running = job->status == JobStatus::running;
    const auto snapshot = running || with_mesh ? ctx.jobs.snapshot(id) : nullptr;
    std::string document;
    if (running) {
        document = running_result(ctx, *job, snapshot.get()).dump();
    } else if (auto stored = ctx.store.result(id)) {
        document = std::move(*stored);
    } else {
        return error_response(
            request, http::status::not_found, "no_result",
            "job " + id + " was " + to_string(job->status) + " before it produced a result");
    }
    // A running job's newest snapshot, or a finished job's final one: the solved mesh.
    if (with_mesh && snapshot) document = add_mesh(std::move(document), snapshot->mesh());
    return text_response(request, http::status::ok, document + "\n", "application/json");
}

Response get_result_glb(ServiceContext& ctx, const Request& request, const std::string& id) {
    const auto job = ctx.jobs.find(id);
    const auto stored = ctx.store.find(id, true);
    if (!job || !stored) return unknown_job(request, id);
    if (job->status == JobStatus::queued) return not_ready(request, id);
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

Response cancel_job(ServiceContext& ctx, const Request& request, const std::string& id) {
    std::optional<JobRecord> job;
    try {
        job = ctx.jobs.cancel(id);
    } catch (const StoreError& e) {
        // A cancel answered 202 must survive a restart; one the store cannot keep is refused.
        Response response =
            error_response(request, http::status::service_unavailable, "store_unwritable",
                           std::string("the cancel could not be stored: ") + e.what());
        response.set(http::field::retry_after, kRetryAfterSeconds);
        return response;
    }
    if (!job) return unknown_job(request, id);
    // 202 while a solve is still stopping (running, or just taken from the queue by a worker);
    // 200 once the state is final.
    const bool stopping = job->status == JobStatus::running || job->status == JobStatus::queued;
    return job_response(request, stopping ? http::status::accepted : http::status::ok, *job);
}

Response list_jobs(ServiceContext& ctx, const Request& request, const Query& query) {
    std::size_t limit = kDefaultPageSize;
    if (const auto it = query.find("limit"); it != query.end()) {
        const std::string& text = it->second;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), limit);
        if (ec != std::errc{} || end != text.data() + text.size() || limit < 1 ||
            limit > kMaxPageSize) {
            return error_response(
                request, http::status::bad_request, "invalid_query",
                "limit must be an integer from 1 to " + std::to_string(kMaxPageSize));
        }
    }
    std::string after;
    if (const auto it = query.find("after"); it != query.end()) after = it->second;
    // One extra row tells whether there is a next page.
    std::vector<JobRecord> jobs = ctx.store.list(limit + 1, after);
    const bool more = jobs.size() > limit;
    if (more) jobs.resize(limit);
    nlohmann::json list = nlohmann::json::array();
    for (JobRecord& job : jobs) {
        if (const auto live = ctx.jobs.find(job.id)) job = *live;
        list.push_back(job_to_json(job));
    }
    nlohmann::json body = {{"jobs", std::move(list)}, {"next", nullptr}};
    if (more) body["next"] = jobs.back().id;
    return json_response(request, http::status::ok, body);
}

Response healthz(ServiceContext& ctx, const Request& request) {
    // Liveness: the process is up and its I/O threads answer, so 200 whatever the store's state
    // (a restart would not bring a store back; /readyz says whether to send traffic). The body
    // says what the store's last write found, without asking it again.
    const StoreHealth store = ctx.store.last_known_health();
    nlohmann::json body = {{"status", "ok"}, {"store", store.writable ? "writable" : "unwritable"}};
    if (!store.writable) body["store_reason"] = store.reason;
    return json_response(request, http::status::ok, body);
}

Response readyz(ServiceContext& ctx, const Request& request) {
    if (ctx.jobs.shutting_down()) {
        return error_response(request, http::status::service_unavailable, "shutting_down",
                              "the service is shutting down");
    }
    const StoreHealth store = ctx.store.health();
    if (!store.writable) {
        return error_response(request, http::status::service_unavailable, "store_unwritable",
                              store.reason);
    }
    return json_response(request, http::status::ok, {{"status", "ready"}});
}

Response metrics(ServiceContext& ctx, const Request& request) {
    return text_response(request, http::status::ok,
                         ctx.metrics.render(ctx.store.count_by_status(), ctx.jobs.queue_length()),
                         "text/plain; version=0.0.4");
}

Response openapi(const Request& request) {
    return text_response(request, http::status::ok, std::string(openapi_yaml()),
                         "application/yaml");
}

Response not_found(const Request& request) {
    return error_response(request, http::status::not_found, "not_found",
                          "no such resource: " + std::string(request.target()));
}

}  // namespace radiant::server::handlers
