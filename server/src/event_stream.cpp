#include "radiant/server/event_stream.h"

#include <nlohmann/json.hpp>

namespace radiant::server {

std::string EventStream::next(const JobRecord& job) {
    if (finished_) return {};
    std::string out;
    const JobProgress& p = job.progress;
    if (p.sequence > last_sent_) {
        last_sent_ = p.sequence;
        const nlohmann::json data = {{"id", job.id},
                                     {"status", to_string(job.status)},
                                     {"stage", p.stage},
                                     {"fraction", p.fraction},
                                     {"iterations", p.iterations},
                                     {"unshot_fraction", p.unshot_fraction},
                                     {"error_estimate", p.error_estimate},
                                     {"elapsed_seconds", p.elapsed_seconds},
                                     {"rays", p.rays}};
        out += "event: progress\nid: " + std::to_string(p.sequence) + "\ndata: " + data.dump() +
               "\n\n";
    }
    if (is_terminal(job.status)) {
        nlohmann::json data = {{"id", job.id}, {"status", to_string(job.status)}};
        if (!job.error.empty()) data["error"] = job.error;
        out += "event: done\ndata: " + data.dump() + "\n\n";
        finished_ = true;
    }
    return out;
}

}  // namespace radiant::server
