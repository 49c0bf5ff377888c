// Progressive snapshots for the observer at a bounded rate, through every phase of a solve.
// Solvers offer the current radiosity when they have some; phases that have nothing new to show
// for a while (linking, a long sweep or LU, the sensor gather) are covered by a heartbeat thread
// that republishes the latest mesh with the current progress, so a viewer hears from the solve
// at least every 1.5 intervals once the first patch mesh exists.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>

#include "radiant/solve.h"

namespace radiant {

class SnapshotPublisher {
public:
    using Clock = std::chrono::steady_clock;

    /// No observer: every call is a no-op and no thread starts.
    SnapshotPublisher(SolveObserver* observer, double interval_seconds, Clock::time_point start);
    ~SnapshotPublisher();
    SnapshotPublisher(const SnapshotPublisher&) = delete;
    SnapshotPublisher& operator=(const SnapshotPublisher&) = delete;

    /// The progress that snapshots carry from now on (elapsed time is filled in at publication).
    void note_progress(const Progress& progress);
    /// Makes `mesh` the latest state and publishes it now when due, else when the interval has
    /// passed. `mesh_version` changes exactly when the triangles do. Sensor values, when given,
    /// replace the latest ones.
    void offer(std::shared_ptr<const SolvedMesh> mesh, std::uint64_t mesh_version,
               std::shared_ptr<const std::vector<SensorResult>> sensors = nullptr);
    /// Whether an offer now would be published at once (the interval has passed).
    bool due() const;
    /// Stops the heartbeat and publishes the final snapshot (the result's values) at once.
    void finish(std::shared_ptr<const SolvedMesh> mesh, std::uint64_t mesh_version,
                std::shared_ptr<const std::vector<SensorResult>> sensors, const Progress& progress);

private:
    void publish_locked(bool final);
    void heartbeat();
    void stop();

    SolveObserver* observer_;
    const Clock::duration interval_;
    const Clock::time_point start_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
    Progress progress_;
    std::shared_ptr<const SolvedMesh> mesh_;
    std::shared_ptr<const std::vector<SensorResult>> sensors_;
    std::uint64_t mesh_version_ = 0;
    bool latest_sent_ = true;
    std::uint64_t version_ = 0;
    Clock::time_point last_sent_;
    std::thread thread_;
};

}  // namespace radiant
