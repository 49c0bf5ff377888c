#include "radiant/server/event_stream.h"

#include <algorithm>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace radiant::server {
namespace {

std::string event(const char* name, std::uint64_t id, const std::string& data) {
    return std::string("event: ") + name + "\nid: " + std::to_string(id) + "\ndata: " + data +
           "\n\n";
}

}  // namespace

std::string EventStream::next(const JobRecord& job, const JobSnapshot* snapshot) {
    if (finished_) return {};
    std::vector<std::pair<std::uint64_t, std::string>> events;
    if (snapshot && snapshot->info().radiosity_event_id > last_sent_) {
        const SnapshotInfo& info = snapshot->info();
        // A client has the mesh if this connection sent it, or if it resumed after its event.
        const bool has_mesh =
            mesh_sent_ == info.mesh_version || resumed_after_ >= info.mesh_event_id;
        if (!has_mesh) {
            events.emplace_back(info.mesh_event_id,
                                event("mesh", info.mesh_event_id, snapshot->mesh_event()));
            mesh_sent_ = info.mesh_version;
        }
        // Likewise the values: sent or resumed after, unless this is the final event.
        const bool has_values =
            info.values_event_id != 0 && !info.final &&
            (values_sent_ == info.values_event_id || resumed_after_ >= info.values_event_id);
        events.emplace_back(info.radiosity_event_id, event("radiosity", info.radiosity_event_id,
                                                           snapshot->radiosity_event(!has_values)));
        values_sent_ = info.values_event_id;
    }
    const JobProgress& p = job.progress;
    if (p.sequence > last_sent_) {
        nlohmann::json data = progress_to_json(p);
        data["id"] = job.id;
        data["status"] = to_string(job.status);
        events.emplace_back(p.sequence, event("progress", p.sequence, data.dump()));
    }
    std::sort(events.begin(), events.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::string out;
    for (auto& [id, text] : events) {
        out += text;
        last_sent_ = std::max(last_sent_, id);
    }
    if (is_terminal(job.status)) {
        nlohmann::json data = {{"id", job.id}, {"status", to_string(job.status)}};
        if (!job.error.empty()) data["error"] = job.error;
        // A finished job's last progress event comes after all its others; `done` follows it.
        out += event("done", p.sequence + 1, data.dump());
        finished_ = true;
    }
    return out;
}

}  // namespace radiant::server
