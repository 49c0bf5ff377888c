#include "radiant/server/job.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <mutex>
#include <random>

#include "radiant/proto/significant_digits.h"

namespace radiant::server {

const char* to_string(JobStatus status) {
    switch (status) {
        case JobStatus::queued:
            return "queued";
        case JobStatus::running:
            return "running";
        case JobStatus::done:
            return "done";
        case JobStatus::failed:
            return "failed";
        case JobStatus::cancelled:
            return "cancelled";
    }
    return "failed";
}

std::optional<JobStatus> parse_job_status(std::string_view text) {
    for (JobStatus s : {JobStatus::queued, JobStatus::running, JobStatus::done, JobStatus::failed,
                        JobStatus::cancelled}) {
        if (text == to_string(s)) return s;
    }
    return std::nullopt;
}

bool is_terminal(JobStatus status) {
    return status == JobStatus::done || status == JobStatus::failed ||
           status == JobStatus::cancelled;
}

nlohmann::json job_progress_json(const JobProgress& p) {
    using proto::kDefaultDigits;
    using proto::kEstimateDigits;
    return {{"stage", p.stage},
            {"fraction", proto::round_significant(p.fraction, kDefaultDigits)},
            {"iterations", p.iterations},
            {"unshot_fraction", proto::round_up_significant(p.unshot_fraction, kEstimateDigits)},
            {"error_estimate", p.error_estimate ? nlohmann::json(proto::round_up_significant(
                                                      *p.error_estimate, kEstimateDigits))
                                                : nlohmann::json(nullptr)},
            {"elapsed_seconds", proto::round_significant(p.elapsed_seconds, kDefaultDigits)}};
}

nlohmann::json progress_to_json(const JobProgress& p) {
    nlohmann::json json = job_progress_json(p);
    json["sequence"] = p.sequence;
    json["rays"] = p.rays;
    return json;
}

JobProgress progress_from_json(const nlohmann::json& json) {
    JobProgress p;
    if (!json.is_object()) return p;
    auto get = [&json](const char* key, auto& field) {
        const auto it = json.find(key);
        if (it == json.end()) return;
        using T = std::decay_t<decltype(field)>;
        if constexpr (std::is_same_v<T, std::string>) {
            if (it->is_string()) field = it->template get<std::string>();
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
            if (it->is_number()) field = it->template get<double>();
        } else {
            if (it->is_number()) field = it->template get<T>();
        }
    };
    get("sequence", p.sequence);
    get("stage", p.stage);
    get("fraction", p.fraction);
    get("iterations", p.iterations);
    get("unshot_fraction", p.unshot_fraction);
    get("error_estimate", p.error_estimate);
    get("elapsed_seconds", p.elapsed_seconds);
    get("rays", p.rays);
    return p;
}

UnixMillis now_millis() {
    using namespace std::chrono;
    return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

std::string iso8601(UnixMillis millis) {
    const std::time_t seconds = static_cast<std::time_t>(millis / 1000);
    std::tm utc{};
    gmtime_r(&seconds, &utc);
    std::array<char, 64> text{};  // room for any int year, so no truncation
    std::snprintf(text.data(), text.size(), "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ",
                  utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min,
                  utc.tm_sec, static_cast<int>(millis % 1000));
    return text.data();
}

bool is_job_id(std::string_view text) {
    return text.size() == 32 && std::all_of(text.begin(), text.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

nlohmann::json job_to_json(const JobRecord& job) {
    auto time_or_null = [](UnixMillis t) -> nlohmann::json {
        return t ? nlohmann::json(iso8601(t)) : nlohmann::json(nullptr);
    };
    const JobProgress& p = job.progress;
    nlohmann::json json = {{"id", job.id},
                           {"status", to_string(job.status)},
                           {"progress", job_progress_json(p)},
                           {"created", time_or_null(job.created)},
                           {"started", time_or_null(job.started)},
                           {"finished", time_or_null(job.finished)},
                           {"warnings", job.warnings}};
    if (!job.error.empty()) json["error"] = job.error;
    return json;
}

std::string new_job_id() {
    // random_device alone can be slow or weak on some platforms; it seeds a 64-bit engine once.
    static std::mutex mutex;
    static std::mt19937_64 engine{[] {
        std::random_device device;
        std::seed_seq seq{device(), device(), device(), device(), device(), device()};
        return std::mt19937_64(seq);
    }()};
    const std::lock_guard lock(mutex);
    std::array<char, 33> text{};
    std::snprintf(text.data(), text.size(), "%016llx%016llx",
                  static_cast<unsigned long long>(engine()),
                  static_cast<unsigned long long>(engine()));
    return text.data();
}

}  // namespace radiant::server
