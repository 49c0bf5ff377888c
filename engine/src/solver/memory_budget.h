// The solve's memory budget (SolveOptions::max_memory_bytes) as a ledger: each step estimates
// what it will allocate before it allocates, asks whether that fits, and holds it while its data
// lives. A step that does not fit is not taken: refinement stops there (the result is `stopped`,
// saying why), and a solve whose first steps do not fit fails before allocating them.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <string>

namespace radiant {

class MemoryBudget {
public:
    /// `limit_bytes` 0: no limit.
    explicit MemoryBudget(std::size_t limit_bytes) : limit_(limit_bytes) {}
    MemoryBudget(const MemoryBudget&) = delete;
    MemoryBudget& operator=(const MemoryBudget&) = delete;

    std::size_t limit_bytes() const { return limit_; }
    std::size_t held_bytes() const { return held_.load(std::memory_order_relaxed); }
    /// Whether `more_bytes` on top of what is held stay within the limit.
    bool fits(std::size_t more_bytes) const {
        return limit_ == 0 || more_bytes <= limit_ - std::min(limit_, held_bytes());
    }
    /// What can still be held (the limit when there is none: callers compare, never add).
    std::size_t available_bytes() const {
        return limit_ == 0 ? static_cast<std::size_t>(-1) : limit_ - std::min(limit_, held_bytes());
    }
    /// "about 350 MiB for <step>, with 120 MiB held, do not fit the memory budget of 200 MiB".
    std::string refusal(const std::string& step, std::size_t needed_bytes) const;
    /// The most held since the last restart_peak (or since the budget was made).
    std::size_t peak_bytes() const { return peak_.load(std::memory_order_relaxed); }
    /// Starts measuring the peak afresh from what is held now, which it returns.
    std::size_t restart_peak();

private:
    friend class MemoryHold;
    const std::size_t limit_;
    std::atomic<std::size_t> held_{0};
    std::atomic<std::size_t> peak_{0};
};

/// Bytes held in a budget for as long as this lives; movable, resizable.
class MemoryHold {
public:
    MemoryHold() = default;
    MemoryHold(MemoryBudget& budget, std::size_t bytes) : budget_(&budget) { resize(bytes); }
    ~MemoryHold() { resize(0); }
    MemoryHold(MemoryHold&& other) noexcept : budget_(other.budget_), bytes_(other.bytes_) {
        other.bytes_ = 0;
    }
    MemoryHold& operator=(MemoryHold&& other) noexcept;
    MemoryHold(const MemoryHold&) = delete;
    MemoryHold& operator=(const MemoryHold&) = delete;

    /// Holds `bytes` instead of what it held (the data grew or shrank).
    void resize(std::size_t bytes);
    std::size_t bytes() const { return bytes_; }

private:
    MemoryBudget* budget_ = nullptr;
    std::size_t bytes_ = 0;
};

/// Bytes in MiB, for messages.
std::string mebibytes_text(std::size_t bytes);

}  // namespace radiant
