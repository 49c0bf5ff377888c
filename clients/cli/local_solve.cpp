#include "local_solve.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>

#include "exit_codes.h"
#include "progress_text.h"
#include "radiant/proto/scene_json.h"
#include "radiant/proto/warnings_json.h"
#include "radiant/solve.h"

namespace radiant::cli {
namespace {

// Reading a scene file holds about this many bytes per byte of JSON at its peak (the parsed
// document and the scene made from it; measured 9–13 on the furnished office and floors), and a
// little more for small files.
constexpr double kParseBytesPerFileByte = 10;
constexpr std::size_t kParseFixedBytes = 2u << 20;

std::size_t mebibytes(double mb) { return static_cast<std::size_t>(mb * 1024 * 1024); }

/// Resident memory of this process now (Linux), 0 if unknown.
std::size_t resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages_total = 0, pages_resident = 0;
    if (!(statm >> pages_total >> pages_resident)) return 0;
    return pages_resident * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

/// What the process held before it read a scene (code, libraries): the part of --max-memory-mb
/// that neither reading nor solving can have. Fixed at the first call.
std::size_t process_base_bytes() {
    static const std::size_t base = resident_bytes();
    return base;
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
                     100 * p.fraction, p.iterations, estimate_text(p.error_estimate).c_str(),
                     p.elapsed_seconds);
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
        std::fprintf(stderr, " error %s", estimate_text(p.error_estimate).c_str());
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

/// Prints why the solve failed, if it did; true then.
bool report_failed_solve(const Result& result) {
    if (result.status != SolveStatus::failed) return false;
    std::cerr << "radiant: solve failed: " << result.error << '\n';
    return true;
}

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
                        "memory budget of the whole process: reading the scene and solving it "
                        "(default: half the physical memory for the solve)")
            ->check(CLI::PositiveNumber),
        command.add_flag("--strict", flags.strict,
                         "warnings are errors: exit 2 and write nothing when the scene or the "
                         "solve has any"),
        command.add_flag("--progress", flags.progress,
                         "print every progressive snapshot (error, rays, elements, links, sensor "
                         "averages) as a line on stderr")};
}

std::optional<Scene> load_checked_scene(const std::string& scene_file, const SolveFlags& flags) {
    const std::size_t base = process_base_bytes();
    std::error_code ec;
    const std::uintmax_t file_bytes = std::filesystem::file_size(scene_file, ec);
    if (flags.max_memory_mb && !ec) {
        const auto reading =
            base + kParseFixedBytes +
            static_cast<std::size_t>(kParseBytesPerFileByte * static_cast<double>(file_bytes));
        if (reading > mebibytes(*flags.max_memory_mb)) {
            std::cerr << "radiant: reading " << scene_file << " ("
                      << (file_bytes + (1u << 20) - 1) / (1u << 20) << " MiB) takes about "
                      << (reading >> 20) << " MiB, more than --max-memory-mb "
                      << *flags.max_memory_mb << '\n';
            return std::nullopt;
        }
    }
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
        // The solve's budget holds the scene and everything the solver allocates; the process's
        // own base is not the solve's to use.
        const std::size_t limit = mebibytes(*flags.max_memory_mb);
        options.max_memory_bytes =
            std::max<std::size_t>(1, limit - std::min(limit, process_base_bytes()));
    }
    options.want_mesh = want_mesh;
    options.strict = options.strict || flags.strict;
    if (flags.progress) {
        SnapshotLines lines;
        return solve(scene, options, &lines);
    }
    std::optional<ProgressLine> progress;
    if (::isatty(STDERR_FILENO)) progress.emplace();
    return solve(scene, options, progress ? &*progress : nullptr);
}

bool report_warnings(const std::string& scene_file, const std::vector<Warning>& warnings,
                     bool strict) {
    for (const Warning& w : warnings) std::cerr << proto::format_warning(scene_file, w) << '\n';
    return strict && !warnings.empty();
}

std::optional<int> report_solve(const std::string& scene_file, const Scene& scene,
                                const SolveFlags& flags, const Result& result) {
    if (report_warnings(scene_file, result.warnings, flags.strict || scene.settings.strict))
        return kExitBadInput;
    if (report_failed_solve(result)) return kExitFailure;
    return std::nullopt;
}

}  // namespace radiant::cli
