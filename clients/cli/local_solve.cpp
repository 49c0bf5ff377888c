#include "local_solve.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <mutex>

#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace radiant::cli {
namespace {

/// The error estimate as the progress lines show it: "-" until the solve has one.
std::string estimate_text(const Progress& p) {
    if (!p.error_estimate) return "    -    ";
    char text[32];
    std::snprintf(text, sizeof text, "%.2e", *p.error_estimate);
    return text;
}

/// One progress line on stderr, rewritten in place with \r. Only used when stderr is a terminal,
/// so logs and pipes never see control characters.
class ProgressLine : public SolveObserver {
public:
    ~ProgressLine() override {
        if (printed_) std::fputc('\n', stderr);
    }

    void on_progress(const Progress& p) override {
        const std::lock_guard lock(mutex_);
        // Throttled: solvers may report thousands of times a second.
        const auto now = std::chrono::steady_clock::now();
        if (printed_ && now - last_ < std::chrono::milliseconds(100) && p.fraction < 1) return;
        last_ = now;
        printed_ = true;
        std::fprintf(stderr, "\r%-12s %5.1f%%  it %zu  err %s  %.1fs   ", p.stage.c_str(),
                     100 * p.fraction, p.iterations, estimate_text(p).c_str(), p.elapsed_seconds);
        std::fflush(stderr);
    }

private:
    std::mutex mutex_;
    bool printed_ = false;
    std::chrono::steady_clock::time_point last_;
};

/// Every snapshot as one line on stderr: what the solve has reached, its error bound and work,
/// and each sensor set's average and minimum once the solver has sensor values.
class SnapshotLines : public SolveObserver {
public:
    void on_progress(const Progress&) override {}

    void on_snapshot(const Snapshot& s) override {
        const Progress& p = s.progress;
        const std::lock_guard lock(mutex_);
        std::fprintf(stderr, "snapshot %3llu%s %7.2f s  %-12s",
                     static_cast<unsigned long long>(s.version), s.final ? " (final)" : "",
                     p.elapsed_seconds, p.stage.c_str());
        std::fprintf(stderr, " error %s", estimate_text(p).c_str());
        std::fprintf(stderr, "  rays %llu  elements %zu  links %zu",
                     static_cast<unsigned long long>(p.rays), p.elements, p.links);
        if (s.sensors) {
            for (const SensorResult& set : *s.sensors) {
                std::fprintf(stderr, "  %s: %.1f lx (min %.1f)", set.name.c_str(), set.average,
                             set.min);
            }
        }
        std::fputc('\n', stderr);
    }

private:
    std::mutex mutex_;
};

}  // namespace

std::vector<CLI::Option*> add_solve_flags(CLI::App& command, SolveFlags& flags) {
    return {
        command.add_option("--tolerance", flags.tolerance, "target relative error, in (0, 1)")
            ->check(CLI::Validator(
                [](const std::string& s) -> std::string {
                    double t = 0;
                    const bool number = CLI::detail::lexical_cast(s, t);
                    return number && t > 0 && t < 1 ? "" : "tolerance must be in (0, 1)";
                },
                "(0,1)")),
        command.add_option("--max-seconds", flags.max_seconds, "wall-clock budget")
            ->check(CLI::PositiveNumber),
        command.add_option("--threads", flags.threads, "worker threads, 0 for all cores")
            ->check(CLI::NonNegativeNumber),
        command.add_option("--seed", flags.seed, "sampling seed (results repeat for a seed)"),
        command.add_option("--method", flags.method, "solver")
            ->check(CLI::IsMember(solver_names())),
        command
            .add_option("--max-memory-mb", flags.max_memory_mb,
                        "memory budget of the hierarchical solver (default: half the physical "
                        "memory)")
            ->check(CLI::PositiveNumber),
        command.add_flag("--progress", flags.progress,
                         "print every progressive snapshot (error, rays, elements, links, sensor "
                         "averages) as a line on stderr")};
}

std::optional<Scene> load_checked_scene(const std::string& scene_file) {
    proto::ParseOutcome outcome = proto::load_scene_file(scene_file);
    for (const Problem& p : outcome.problems) {
        std::cerr << proto::format_problem(scene_file, p) << '\n';
    }
    return std::move(outcome.scene);
}

Result solve_locally(const Scene& scene, const SolveFlags& flags, bool want_mesh) {
    SolveOptions options = options_from(scene.settings);
    if (flags.tolerance) options.tolerance = *flags.tolerance;
    if (flags.max_seconds) options.max_seconds = *flags.max_seconds;
    if (flags.threads) options.threads = *flags.threads;
    if (flags.method) options.method = *flags.method;
    if (flags.seed) options.seed = *flags.seed;
    if (flags.max_memory_mb) {
        options.max_memory_bytes = static_cast<std::size_t>(*flags.max_memory_mb * 1024 * 1024);
    }
    options.want_mesh = want_mesh;
    if (flags.progress) {
        SnapshotLines lines;
        return solve(scene, options, &lines);
    }
    std::optional<ProgressLine> progress;
    if (::isatty(STDERR_FILENO)) progress.emplace();
    return solve(scene, options, progress ? &*progress : nullptr);
}

bool report_failed_solve(const Result& result) {
    if (result.status != SolveStatus::failed) return false;
    std::cerr << "radiant: solve failed: " << result.error << '\n';
    return true;
}

}  // namespace radiant::cli
