// The latest progressive snapshot of a job, as event streams and running results read it. The
// solver hands over its mesh by pointer (no copy on the solving thread); the compact form and
// the JSON texts are made on first use by whichever reader needs them, once, for all readers.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "radiant/result.h"
#include "radiant/server/compact_mesh.h"
#include "radiant/server/job.h"

namespace radiant::server {

/// Where a snapshot sits in the job's event-id sequence, and what it reports.
struct SnapshotInfo {
    std::uint64_t version = 0;             ///< the engine's snapshot version
    std::uint64_t mesh_version = 0;        ///< changes exactly when the triangles do
    std::uint64_t mesh_event_id = 0;       ///< id of the `mesh` event of this mesh_version
    std::uint64_t radiosity_event_id = 0;  ///< id of this snapshot's `radiosity` event
    /// Id of the first `radiosity` event with this snapshot's values: the engine repeats its
    /// latest values while it links, gathers and checks, and a client that has them is not sent
    /// them again. 0: unknown (always sent).
    std::uint64_t values_event_id = 0;
    bool final = false;    ///< its values are the result's
    JobProgress progress;  ///< when it was taken
    /// The latest sensor values the solver had (null before it had any, and when restored).
    std::shared_ptr<const std::vector<SensorResult>> sensors;
};

class JobSnapshot {
public:
    /// A live snapshot: `mesh` is shared with the engine and converted only when read.
    JobSnapshot(std::string job_id, SnapshotInfo info, std::shared_ptr<const SolvedMesh> mesh);
    /// A stored one (a finished job's final snapshot).
    JobSnapshot(std::string job_id, SnapshotInfo info, CompactMesh mesh);

    const SnapshotInfo& info() const { return info_; }
    /// The engine's mesh of a live snapshot (null for a stored one): a repeat shares it.
    const SolvedMesh* source() const { return source_.get(); }
    /// Thread-safe; computed on the first call.
    const CompactMesh& mesh() const;
    /// The data of the `mesh` event: {"id", "mesh_version", "encoding", vertices, triangles,
    /// triangle_surface}, the arrays in base64 (geometry_base64_json).
    const std::string& mesh_event() const;
    /// The data of the `radiosity` event: {"id", "mesh_version", "version", "final", "encoding",
    /// progress fields, triangle_radiosity, vertex_radiosity}, the arrays in base64; or, for a
    /// client that has this snapshot's values already, "values_event" (values_event_id) in
    /// place of the arrays.
    const std::string& radiosity_event(bool with_values = true) const;

private:
    std::string job_id_;
    SnapshotInfo info_;
    std::shared_ptr<const SolvedMesh> source_;
    mutable std::once_flag compact_once_, mesh_once_, radiosity_once_, repeat_once_;
    mutable CompactMesh mesh_;
    mutable std::string mesh_event_, radiosity_event_, repeat_event_;
};

}  // namespace radiant::server
