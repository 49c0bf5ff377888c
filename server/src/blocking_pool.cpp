#include "radiant/server/blocking_pool.h"

#include <boost/asio/post.hpp>
#include <utility>

namespace radiant::server {

BlockingPool::BlockingPool(std::size_t threads, std::size_t max_waiting)
    : capacity_(threads + max_waiting), pool_(threads) {}

BlockingPool::~BlockingPool() {
    pool_.stop();
    pool_.join();
}

bool BlockingPool::try_post(std::function<void()> task) {
    if (queued_.fetch_add(1) >= capacity_) {
        queued_.fetch_sub(1);
        return false;
    }
    boost::asio::post(pool_, [this, task = std::move(task)] {
        task();
        queued_.fetch_sub(1);
    });
    return true;
}

}  // namespace radiant::server
