#include "postgres_change_feed.h"

#include <libpq-fe.h>
#include <poll.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <stdexcept>
#include <utility>

#include "postgres_connection.h"

namespace radiant::server {
namespace {

/// A lost connection is opened again this late: soon enough that a stream falls back to
/// reading every poll only briefly, rarely enough not to hammer a database that is down.
constexpr auto kReconnectDelay = std::chrono::seconds(1);

std::size_t slot_of(const std::string& id, std::size_t slots) {
    return std::hash<std::string>{}(id) % slots;
}

}  // namespace

PostgresChangeFeed::PostgresChangeFeed(std::string uri) : uri_(std::move(uri)) {
    if (::pipe(wake_pipe_) != 0) throw std::runtime_error("change feed: pipe() failed");
    thread_ = std::thread([this] { listen(); });
}

PostgresChangeFeed::~PostgresChangeFeed() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    stop_wake_.notify_all();
    const char byte = 0;
    [[maybe_unused]] const ssize_t written = ::write(wake_pipe_[1], &byte, 1);
    thread_.join();
    ::close(wake_pipe_[0]);
    ::close(wake_pipe_[1]);
}

std::optional<std::uint64_t> PostgresChangeFeed::token(const std::string& id) const {
    if (!listening_) return std::nullopt;
    const std::uint64_t epoch = epoch_;
    return (epoch << 32) | slots_[slot_of(id, slots_.size())];
}

void PostgresChangeFeed::listen() {
    PGconn* conn = nullptr;
    bool warned = false;  // one log line per outage, not one per retry
    const auto stopping = [this] {
        const std::lock_guard lock(mutex_);
        return stopping_;
    };
    while (!stopping()) {
        if (!conn) {
            try {
                conn = connect_postgres(uri_);
                PGresult* r = PQexec(conn, (std::string("LISTEN ") + kJobChangeChannel).c_str());
                const bool ok = PQresultStatus(r) == PGRES_COMMAND_OK;
                PQclear(r);
                if (!ok) throw std::runtime_error(PQerrorMessage(conn));
                ++epoch_;  // before listening_: a reader never sees the old epoch as current
                listening_ = true;
                warned = false;
            } catch (const std::exception& e) {
                if (!std::exchange(warned, true)) {
                    spdlog::warn("job change feed: {}; streams of other replicas' jobs poll",
                                 e.what());
                }
                PQfinish(conn);
                conn = nullptr;
                std::unique_lock lock(mutex_);
                stop_wake_.wait_for(lock, kReconnectDelay, [this] { return stopping_; });
                continue;
            }
        }
        pollfd fds[2] = {{PQsocket(conn), POLLIN, 0}, {wake_pipe_[0], POLLIN, 0}};
        if (::poll(fds, 2, -1) < 0) continue;  // EINTR
        if (fds[1].revents) break;
        if (!PQconsumeInput(conn)) {
            spdlog::warn("job change feed lost its connection: {}", PQerrorMessage(conn));
            listening_ = false;
            PQfinish(conn);
            conn = nullptr;
            continue;
        }
        while (PGnotify* n = PQnotifies(conn)) {
            ++slots_[slot_of(n->extra, slots_.size())];
            PQfreemem(n);
        }
    }
    listening_ = false;
    PQfinish(conn);
}

}  // namespace radiant::server
