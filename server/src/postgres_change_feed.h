// Wake-ups for readers of jobs that other replicas run: one connection per process LISTENs on
// the store's `radiant_jobs` channel (a trigger NOTIFYs it with the job's id whenever the job's
// state, progress or running snapshot changes), so event streams re-read a job only when it
// changed instead of querying the database at their polling rate, once per client.
#pragma once

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace radiant::server {

/// The NOTIFY channel of job changes, as the store's triggers name it.
inline constexpr const char* kJobChangeChannel = "radiant_jobs";

/// Thread-safe. Runs one thread with its own connection, from construction to destruction.
class PostgresChangeFeed {
public:
    explicit PostgresChangeFeed(std::string uri);
    ~PostgresChangeFeed();
    PostgresChangeFeed(const PostgresChangeFeed&) = delete;
    PostgresChangeFeed& operator=(const PostgresChangeFeed&) = delete;

    /// Changes whenever a notification for `id` arrives, and whenever the feed (re)connects
    /// (notifications sent meanwhile were missed); nothing while it is not listening.
    std::optional<std::uint64_t> token(const std::string& id) const;

private:
    void listen();

    const std::string uri_;
    /// Notifications counted per hash slot: bounded memory whatever the number of jobs; two
    /// jobs sharing a slot only cost a needless read.
    std::array<std::atomic<std::uint32_t>, 1024> slots_{};
    std::atomic<std::uint32_t> epoch_{0};  ///< successful LISTENs so far
    std::atomic<bool> listening_{false};
    int wake_pipe_[2] = {-1, -1};  ///< written to at destruction, to end the thread's poll()
    std::mutex mutex_;
    std::condition_variable stop_wake_;
    bool stopping_ = false;  ///< guarded by mutex_
    std::thread thread_;
};

}  // namespace radiant::server
