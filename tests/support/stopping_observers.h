// Observers that stop a solve at a chosen point of it, deterministically: at the n-th progress
// report of a stage, by a cancel, or by holding the solve there until its time limit has passed.
#pragma once

#include <atomic>
#include <chrono>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "radiant/solve.h"

namespace radiant::testing {

/// Counts the reports of `stage` and acts at the `nth` (1-based).
class AtStageReport : public SolveObserver {
public:
    AtStageReport(std::string stage, int nth) : stage_(std::move(stage)), nth_(nth) {}
    void on_progress(const Progress& p) override {
        if (!first_) first_ = std::chrono::steady_clock::now();
        if (p.stage == stage_ && ++seen_ == nth_) act();
    }
    bool reached() const { return seen_ >= nth_; }

protected:
    virtual void act() = 0;
    /// When the first report came: after the solve began.
    std::chrono::steady_clock::time_point first_report() const { return *first_; }

private:
    std::string stage_;
    int nth_;
    std::atomic<int> seen_{0};
    std::optional<std::chrono::steady_clock::time_point> first_;
};

/// Cancels the solve at the report.
class CancelAtStageReport : public AtStageReport {
public:
    CancelAtStageReport(CancellationToken& token, std::string stage, int nth)
        : AtStageReport(std::move(stage), nth), token_(token) {}

private:
    void act() override { token_.cancel(); }
    CancellationToken& token_;
};

/// Holds the solve at the report until its time limit, `seconds` after it began (which is
/// before the first report), has passed.
class WaitOutTheLimitAtStageReport : public AtStageReport {
public:
    WaitOutTheLimitAtStageReport(double seconds, std::string stage, int nth)
        : AtStageReport(std::move(stage), nth), seconds_(seconds) {}

private:
    void act() override {
        std::this_thread::sleep_until(first_report() + std::chrono::duration<double>(seconds_));
    }
    double seconds_;
};

}  // namespace radiant::testing
