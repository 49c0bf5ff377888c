// What one GET /v1/jobs/{id}/events connection sends next (text/event-stream). Pure: the session
// polls the job and writes what this returns, so tests need no socket and a slow client only
// ever sees fewer, newer events — it never holds up the solver.
//
// Events: `progress`, `mesh` (patch geometry, once per mesh version, before the first
// `radiosity` event of that version), `radiosity` (per-triangle and per-vertex radiosity of the
// latest snapshot) and `done`. Their ids are one increasing sequence per job, so Last-Event-ID
// resumes where the client left off; a resumed client that has not seen the current mesh gets
// it again first. A `radiosity` event whose values the client already has (the engine repeating
// them) comes without its arrays; the final one always has them.
#pragma once

#include <cstdint>
#include <string>

#include "radiant/server/job.h"
#include "radiant/server/job_snapshot.h"

namespace radiant::server {

/// A comment line that keeps proxies and clients from timing out an idle stream.
inline constexpr const char* kKeepAliveComment = ": keep-alive\n\n";

class EventStream {
public:
    /// `last_event_id`: the Last-Event-ID header of a reconnecting client (0 for a new one);
    /// events it has seen are not sent again.
    explicit EventStream(std::uint64_t last_event_id = 0)
        : resumed_after_(last_event_id), last_sent_(last_event_id) {}

    /// The events for the job as it is now, in id order: the newest snapshot's `mesh` (when the
    /// client lacks it) and `radiosity`, and `progress`, each when newer than what was sent;
    /// then `done` once the job is finished. Empty when there is nothing new. `snapshot` is the
    /// job's latest (null if none); read it after `job`, so a finished job's final snapshot is
    /// always there to precede `done`.
    std::string next(const JobRecord& job, const JobSnapshot* snapshot);
    /// True once `done` was returned; the connection then closes.
    bool finished() const { return finished_; }

private:
    const std::uint64_t resumed_after_;
    std::uint64_t last_sent_;
    std::uint64_t mesh_sent_ = 0;    ///< mesh version this connection has sent (0: none)
    std::uint64_t values_sent_ = 0;  ///< values_event_id of the radiosity values it has sent
    bool finished_ = false;
};

}  // namespace radiant::server
