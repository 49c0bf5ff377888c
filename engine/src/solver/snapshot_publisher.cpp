#include "solver/snapshot_publisher.h"

#include <algorithm>
#include <utility>

namespace radiant {
namespace {

// Silence, in intervals, after which the heartbeat repeats the latest snapshot: long enough that
// a solver publishing every interval is never pre-empted by a stale copy of its own state.
constexpr double kHeartbeatSilence = 1.5;
// The heartbeat's shortest wait, so an interval of 0 ("every chance") does not spin.
constexpr auto kMinHeartbeatWait = std::chrono::milliseconds(20);

}  // namespace

SnapshotPublisher::SnapshotPublisher(SolveObserver* observer, double interval_seconds,
                                     Clock::time_point start)
    : observer_(observer),
      interval_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(std::max(interval_seconds, 0.0)))),
      start_(start),
      last_sent_(start) {
    if (observer_) thread_ = std::thread([this] { heartbeat(); });
}

SnapshotPublisher::~SnapshotPublisher() { stop(); }

void SnapshotPublisher::note_progress(const Progress& progress) {
    if (!observer_) return;
    const std::lock_guard lock(mutex_);
    progress_ = progress;
}

void SnapshotPublisher::offer(std::shared_ptr<const SolvedMesh> mesh, std::uint64_t mesh_version,
                              std::shared_ptr<const std::vector<SensorResult>> sensors) {
    if (!observer_) return;
    const std::lock_guard lock(mutex_);
    if (stopping_) return;
    mesh_ = std::move(mesh);
    mesh_version_ = mesh_version;
    if (sensors) sensors_ = std::move(sensors);
    latest_sent_ = false;
    if (Clock::now() - last_sent_ >= interval_) publish_locked(false);
    wake_.notify_all();  // the heartbeat plans its next repeat from this
}

bool SnapshotPublisher::due() const {
    if (!observer_) return false;
    const std::lock_guard lock(mutex_);
    return Clock::now() - last_sent_ >= interval_;
}

void SnapshotPublisher::finish(std::shared_ptr<const SolvedMesh> mesh, std::uint64_t mesh_version,
                               std::shared_ptr<const std::vector<SensorResult>> sensors,
                               const Progress& progress) {
    if (!observer_) return;
    stop();  // no heartbeat may follow the final snapshot
    const std::lock_guard lock(mutex_);
    mesh_ = std::move(mesh);
    mesh_version_ = mesh_version;
    sensors_ = std::move(sensors);
    progress_ = progress;
    publish_locked(true);
}

void SnapshotPublisher::publish_locked(bool final) {
    const Clock::time_point now = Clock::now();
    Snapshot snapshot;
    snapshot.version = ++version_;
    snapshot.mesh_version = mesh_version_;
    snapshot.mesh = mesh_;
    snapshot.sensors = sensors_;
    snapshot.progress = progress_;
    snapshot.progress.elapsed_seconds = std::chrono::duration<double>(now - start_).count();
    snapshot.final = final;
    last_sent_ = now;
    latest_sent_ = true;
    // Under the lock, so versions reach the observer in order; observers are cheap by contract.
    observer_->on_snapshot(snapshot);
}

void SnapshotPublisher::heartbeat() {
    const auto silence = std::chrono::duration_cast<Clock::duration>(interval_ * kHeartbeatSilence);
    std::unique_lock lock(mutex_);
    while (!stopping_) {
        if (!mesh_) {
            wake_.wait(lock);  // nothing to show before the first offer
            continue;
        }
        // A fresh offer that came too early goes out when the interval is over; otherwise the
        // latest state is repeated after a longer silence.
        const Clock::time_point next =
            last_sent_ +
            std::max<Clock::duration>(latest_sent_ ? silence : interval_, kMinHeartbeatWait);
        if (Clock::now() >= next) {
            publish_locked(false);
        } else {
            wake_.wait_until(lock, next);  // an offer or stop() wakes it early to look again
        }
    }
}

void SnapshotPublisher::stop() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
}

}  // namespace radiant
