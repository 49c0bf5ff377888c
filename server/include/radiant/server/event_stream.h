// What one GET /v1/jobs/{id}/events connection sends next (text/event-stream). Pure: the session
// polls the job and writes what this returns, so tests need no socket and a slow client only
// ever sees fewer, newer events — it never holds up the solver.
#pragma once

#include <cstdint>
#include <string>

#include "radiant/server/job.h"

namespace radiant::server {

/// A comment line that keeps proxies and clients from timing out an idle stream.
inline constexpr const char* kKeepAliveComment = ": keep-alive\n\n";

class EventStream {
public:
    /// `last_event_id`: the Last-Event-ID header of a reconnecting client (0 for a new one);
    /// progress already seen is not sent again.
    explicit EventStream(std::uint64_t last_event_id = 0) : last_sent_(last_event_id) {}

    /// The events for the job as it is now: a `progress` event (id = progress sequence) when it
    /// moved since the last one sent, then `done` with the final status once the job is finished.
    /// Empty when there is nothing new.
    std::string next(const JobRecord& job);
    /// True once `done` was returned; the connection then closes.
    bool finished() const { return finished_; }

private:
    std::uint64_t last_sent_;
    bool finished_ = false;
};

}  // namespace radiant::server
