#include "solver/memory_budget.h"

#include <cmath>
#include <cstdio>

namespace radiant {

std::string mebibytes_text(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f MiB", std::ceil(static_cast<double>(bytes) / (1 << 20)));
    return text;
}

std::string MemoryBudget::refusal(const std::string& step, std::size_t needed_bytes) const {
    return "about " + mebibytes_text(needed_bytes) + " for " + step + ", with " +
           mebibytes_text(held_bytes()) + " held, do not fit the memory budget of " +
           mebibytes_text(limit_);
}

MemoryHold& MemoryHold::operator=(MemoryHold&& other) noexcept {
    if (this != &other) {
        resize(0);
        budget_ = other.budget_;
        bytes_ = other.bytes_;
        other.bytes_ = 0;
    }
    return *this;
}

std::size_t MemoryBudget::restart_peak() {
    const std::size_t held = held_bytes();
    peak_.store(held, std::memory_order_relaxed);
    return held;
}

void MemoryHold::resize(std::size_t bytes) {
    if (!budget_) return;
    if (bytes >= bytes_) {
        const std::size_t held =
            budget_->held_.fetch_add(bytes - bytes_, std::memory_order_relaxed) + bytes - bytes_;
        std::size_t peak = budget_->peak_.load(std::memory_order_relaxed);
        while (peak < held &&
               !budget_->peak_.compare_exchange_weak(peak, held, std::memory_order_relaxed)) {
        }
    } else {
        budget_->held_.fetch_sub(bytes_ - bytes, std::memory_order_relaxed);
    }
    bytes_ = bytes;
}

}  // namespace radiant
