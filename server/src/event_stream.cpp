#include "radiant/server/event_stream.h"

#include <nlohmann/json.hpp>

namespace radiant::server {

std::string EventStream::next(const JobRecord& job) {
    if (finished_) return {};
    std::string out;
    const JobProgress& p = job.progress;
    if (p.sequence > last_sent_) {
        last_sent_ = p.sequence;
        nlohmann::json data = progress_to_json(p);
        data["id"] = job.id;
        data["status"] = to_string(job.status);
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
