#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace radiant {

// A stop request (a time limit, a cancel) polled from a long loop, parallel or not: asked at
// every `every`-th step (where asking costs more than a step), and remembered once true, so that
// every thread sees it at its next step.
class StopPoll {
public:
    StopPoll(const std::function<bool()>& should_stop, std::size_t every)
        : should_stop_(should_stop), every_(every) {}

    /// Whether to stop before step `step`.
    bool operator()(std::size_t step) {
        if (step % every_ == 0 && should_stop_ && should_stop_()) stopped_ = true;
        return stopped();
    }
    bool stopped() const { return stopped_.load(std::memory_order_relaxed); }

private:
    const std::function<bool()>& should_stop_;
    const std::size_t every_;
    std::atomic<bool> stopped_{false};
};

}  // namespace radiant
