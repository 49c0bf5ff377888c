// Threads for request work too slow for an I/O thread — pictures and CSV made from stored
// results — so that other connections never wait behind it, and a bound on what may wait.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

#include <boost/asio/thread_pool.hpp>

namespace radiant::server {

class BlockingPool {
public:
    /// `threads` run tasks; at most `max_waiting` more wait for one.
    BlockingPool(std::size_t threads, std::size_t max_waiting);
    /// Runs the tasks already started to their end; waiting ones are dropped.
    ~BlockingPool();

    /// Runs `task` on a pool thread; false, and nothing runs, when `max_waiting` tasks already
    /// wait. Thread-safe. `task` must not throw.
    bool try_post(std::function<void()> task);

private:
    const std::size_t capacity_;          ///< running + waiting
    std::atomic<std::size_t> queued_{0};  ///< tasks posted and not yet finished
    boost::asio::thread_pool pool_;
};

}  // namespace radiant::server
