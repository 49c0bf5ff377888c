#include "radiant/server/job_snapshot.h"

#include <nlohmann/json.hpp>
#include <utility>

namespace radiant::server {
namespace {

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
        mesh_event_ =
            merge({{"id", job_id_}, {"mesh_version", info_.mesh_version}}, geometry_json(mesh()));
    });
    return mesh_event_;
}

const std::string& JobSnapshot::radiosity_event() const {
    std::call_once(radiosity_once_, [this] {
        const JobProgress& p = info_.progress;
        radiosity_event_ = merge({{"id", job_id_},
                                  {"mesh_version", info_.mesh_version},
                                  {"version", info_.version},
                                  {"final", info_.final},
                                  {"stage", p.stage},
                                  {"fraction", p.fraction},
                                  {"iterations", p.iterations},
                                  {"error_estimate", p.error_estimate},
                                  {"elapsed_seconds", p.elapsed_seconds}},
                                 radiosity_json(mesh()));
    });
    return radiosity_event_;
}

}  // namespace radiant::server
