// A job as the service stores and reports it: one submitted scene and what became of it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace radiant::server {

enum class JobStatus { queued, running, done, failed, cancelled };

const char* to_string(JobStatus status);
std::optional<JobStatus> parse_job_status(std::string_view text);
/// done, failed and cancelled never change again.
bool is_terminal(JobStatus status);

/// The progress fields of contract §4, plus the sequence number that SSE event ids use.
struct JobProgress {
    std::uint64_t sequence = 0;  ///< increases with every engine progress report
    std::string stage;
    double fraction = 0;
    std::size_t iterations = 0;
    double unshot_fraction = 0;
    std::optional<double>
        error_estimate;  ///< Progress::error_estimate: none until the solve has one
    double elapsed_seconds = 0;
    std::uint64_t rays = 0;
};

/// Progress numbers as JSON: fractions and seconds to 4 significant digits, the error estimate
/// rounded up to 3 (null until there is one), as in results.
nlohmann::json progress_to_json(const JobProgress& progress);
/// The `progress` object of GET /v1/jobs/{id}: progress_to_json without sequence and rays.
nlohmann::json job_progress_json(const JobProgress& progress);
/// Lenient: missing or mistyped fields keep their defaults (the store wrote them).
JobProgress progress_from_json(const nlohmann::json& json);

/// Milliseconds since the Unix epoch; 0 means "not yet".
using UnixMillis = std::int64_t;
UnixMillis now_millis();
/// ISO 8601 UTC with milliseconds, e.g. 2026-11-23T08:44:39.123Z.
std::string iso8601(UnixMillis millis);

struct JobRecord {
    std::string id;  ///< 32 lowercase hex digits (128 random bits)
    JobStatus status = JobStatus::queued;
    std::string scene_json;
    std::string idempotency_key;  ///< empty when the client sent none
    UnixMillis created = 0, started = 0, finished = 0;
    JobProgress progress;
    std::string error;
    /// The result's `warnings` (radiant-result/1): the scene's once its checks have run, all of
    /// them when the job has finished.
    nlohmann::json warnings = nlohmann::json::array();
    /// The lease token of the claim that runs the job (JobStore::claim); 0 when no claim does.
    std::int64_t lease_token = 0;
};

/// {id, status, progress, created, started, finished, warnings[, error]}: GET /v1/jobs/{id}.
nlohmann::json job_to_json(const JobRecord& job);

/// A fresh random 128-bit id in hex. Thread-safe.
std::string new_job_id();

/// Whether `text` has the form of new_job_id()'s ids: anything else names no job, and never
/// reaches a store (PostgreSQL refuses text that is not UTF-8 outright).
bool is_job_id(std::string_view text);

}  // namespace radiant::server
