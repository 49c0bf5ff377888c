// Finished jobs' group contributions, parsed once: POST /v1/jobs/{id}/scenes then costs a
// weighted sum of them, not a parse of the whole stored result (most of a light scene's time).
#pragma once

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <utility>

#include "radiant/result.h"

namespace radiant::server {

/// The solutions read back for light scenes, least recently used dropped first. A finished
/// job's result never changes, so an entry never goes stale. Bounded by the sensor values the
/// entries hold (memory), not their number. Thread-safe.
class StoredSolutions {
public:
    /// About 8 bytes a value: the default holds 32 MB.
    explicit StoredSolutions(std::size_t max_values = 4000000) : max_values_(max_values) {}

    /// The solution kept for job `id`, or null.
    std::shared_ptr<const Result> find(const std::string& id);
    /// Keeps `solution` of job `id`; one larger than the whole budget is not kept.
    void keep(const std::string& id, std::shared_ptr<const Result> solution);

private:
    struct Entry {
        std::string id;
        std::shared_ptr<const Result> solution;
        std::size_t values = 0;
    };
    std::mutex mutex_;
    std::list<Entry> entries_;  ///< most recently used first
    std::size_t values_ = 0;
    std::size_t max_values_;
};

}  // namespace radiant::server
