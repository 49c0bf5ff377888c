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
    /// `replica` (radiantd --replica): when not empty, every series carries replica="<name>",
    /// so that replicas on one store are told apart however they are scraped.
    explicit Metrics(std::string replica = {});

    void count_request(unsigned status);
    /// Adds one finished solve's wall-clock seconds and rays.
    void count_solve(double seconds, std::uint64_t rays);

    /// The exposition text; `jobs` by state and `queue_length` come from the job store and queue
    /// at scrape time so they are never stale.
    std::string render(const std::map<JobStatus, std::size_t>& jobs,
                       std::size_t queue_length) const;

private:
    /// `{replica="…",name="value"}`, either part left out when empty; "" when both are.
    std::string labels(const std::string& name = {}, const std::string& value = {}) const;

    const std::string replica_;
    mutable std::mutex mutex_;
    std::map<unsigned, std::uint64_t> requests_by_status_;
    std::uint64_t solves_ = 0;
    double solve_seconds_ = 0;
    std::uint64_t rays_ = 0;
};

}  // namespace radiant::server
