#include "radiant/server/job_snapshot.h"

#include <nlohmann/json.hpp>
#include <utility>

namespace radiant::server {
namespace {

/// How the arrays of `mesh` and `radiosity` events are written (docs/service.md).
constexpr const char* kEventArrayEncoding = "base64-le";

/// `head` is a JSON object; `arrays` are more members (no braces) to add to it.
std::string merge(const nlohmann::json& head, const std::string& arrays) {
    std::string out = head.dump();
    out.pop_back();
    out += ',';
    out += arrays;
    out += '}';
    return out;
}

}  // namespace

JobSnapshot::JobSnapshot(std::string job_id, SnapshotInfo info,
                         std::shared_ptr<const SolvedMesh> mesh)
    : job_id_(std::move(job_id)), info_(std::move(info)), source_(std::move(mesh)) {}

JobSnapshot::JobSnapshot(std::string job_id, SnapshotInfo info, CompactMesh mesh)
    : job_id_(std::move(job_id)), info_(std::move(info)), mesh_(std::move(mesh)) {
    std::call_once(compact_once_, [] {});
}

const CompactMesh& JobSnapshot::mesh() const {
    std::call_once(compact_once_, [this] {
        if (source_) mesh_ = compact(*source_);
    });
    return mesh_;
}

const std::string& JobSnapshot::mesh_event() const {
    std::call_once(mesh_once_, [this] {
        mesh_event_ = merge({{"id", job_id_},
                             {"mesh_version", info_.mesh_version},
                             {"encoding", kEventArrayEncoding}},
                            geometry_base64_json(mesh()));
    });
    return mesh_event_;
}

const std::string& JobSnapshot::radiosity_event(bool with_values) const {
    const auto head = [this] {
        nlohmann::json json = job_progress_json(info_.progress);
        json.erase("unshot_fraction");
        json.update({{"id", job_id_},
                     {"mesh_version", info_.mesh_version},
                     {"version", info_.version},
                     {"final", info_.final},
                     {"encoding", kEventArrayEncoding}});
        return json;
    };
    if (!with_values) {
        std::call_once(repeat_once_, [&] {
            nlohmann::json json = head();
            json["values_event"] = info_.values_event_id;
            repeat_event_ = json.dump();
        });
        return repeat_event_;
    }
    std::call_once(radiosity_once_,
                   [&] { radiosity_event_ = merge(head(), radiosity_base64_json(mesh())); });
    return radiosity_event_;
}

}  // namespace radiant::server
