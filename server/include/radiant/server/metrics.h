// Counters for GET /metrics (Prometheus text format 0.0.4). Thread-safe.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include "radiant/server/job.h"

namespace radiant::server {

class Metrics {
public:
    void count_request(unsigned status);
    /// Adds one finished solve's wall-clock seconds and rays.
    void count_solve(double seconds, std::uint64_t rays);

    /// The exposition text; `jobs` by state and `queue_length` come from the job store and queue
    /// at scrape time so they are never stale.
    std::string render(const std::map<JobStatus, std::size_t>& jobs,
                       std::size_t queue_length) const;

private:
    mutable std::mutex mutex_;
    std::map<unsigned, std::uint64_t> requests_by_status_;
    std::uint64_t solves_ = 0;
    double solve_seconds_ = 0;
    std::uint64_t rays_ = 0;
};

}  // namespace radiant::server
