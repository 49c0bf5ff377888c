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
    bool final = false;                    ///< its values are the result's
    JobProgress progress;                  ///< when it was taken
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
    /// Thread-safe; computed on the first call.
    const CompactMesh& mesh() const;
    /// The data of the `mesh` event: {"id", "mesh_version", vertices, triangles, triangle_surface}.
    const std::string& mesh_event() const;
    /// The data of the `radiosity` event: {"id", "mesh_version", "version", "final", progress
    /// fields, triangle_radiosity, vertex_radiosity}.
    const std::string& radiosity_event() const;

private:
    std::string job_id_;
    SnapshotInfo info_;
    std::shared_ptr<const SolvedMesh> source_;
    mutable std::once_flag compact_once_, mesh_once_, radiosity_once_;
    mutable CompactMesh mesh_;
    mutable std::string mesh_event_, radiosity_event_;
};

}  // namespace radiant::server
