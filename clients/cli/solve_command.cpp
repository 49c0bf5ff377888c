#include "solve_command.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "atomic_file.h"
#include "exit_codes.h"
#include "radiant/proto/result_gltf.h"
#include "radiant/proto/result_json.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace radiant::cli {
namespace {

struct SolveArgs {
    std::string scene;
    std::string out;
    std::string gltf;
    std::optional<double> tolerance;
    std::optional<double> max_seconds;
    std::optional<int> threads;
    std::optional<std::string> method;
    bool mesh = false;
};

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
        std::fprintf(stderr, "\r%-12s %5.1f%%  it %zu  err %.2e  %.1fs   ", p.stage.c_str(),
                     100 * p.fraction, p.iterations, p.error_estimate, p.elapsed_seconds);
        std::fflush(stderr);
    }

private:
    std::mutex mutex_;
    bool printed_ = false;
    std::chrono::steady_clock::time_point last_;
};

int run_solve(const SolveArgs& args) {
    const proto::ParseOutcome outcome = proto::load_scene_file(args.scene);
    if (!outcome.ok()) {
        for (const Problem& p : outcome.problems) {
            std::cerr << proto::format_problem(args.scene, p) << '\n';
        }
        return kExitBadInput;
    }
    SolveOptions options = options_from(outcome.scene->settings);
    if (args.tolerance) options.tolerance = *args.tolerance;
    if (args.max_seconds) options.max_seconds = *args.max_seconds;
    if (args.threads) options.threads = *args.threads;
    if (args.method) options.method = *args.method;
    options.want_mesh = args.mesh || !args.gltf.empty();

    Result result;
    {
        std::optional<ProgressLine> progress;
        if (::isatty(STDERR_FILENO)) progress.emplace();
        result = solve(*outcome.scene, options, progress ? &*progress : nullptr);
    }
    if (!args.gltf.empty() && result.status != SolveStatus::failed) {
        write_file_atomically(args.gltf, proto::result_to_glb(result, *outcome.scene));
    }
    if (!args.mesh) result.mesh.reset();  // requested for the glTF only
    const std::string text = proto::result_to_json(result).dump(2) + "\n";
    if (args.out.empty()) {
        std::cout << text << std::flush;
    } else {
        write_file_atomically(args.out, text);
    }
    if (result.status == SolveStatus::failed) {
        std::cerr << "radiant: solve failed: " << result.error << '\n';
        return kExitFailure;
    }
    return kExitOk;
}

}  // namespace

void add_solve_command(CLI::App& app, int& exit_code) {
    auto* cmd =
        app.add_subcommand("solve", "Solve a scene; the result JSON goes to stdout or --out");
    auto args = std::make_shared<SolveArgs>();
    cmd->add_option("scene", args->scene, "radiant-scene/1 JSON file")->required();
    cmd->add_option("--out", args->out, "write the result here (atomically) instead of stdout");
    cmd->add_option("--tolerance", args->tolerance, "target relative error, in (0, 1)")
        ->check(CLI::Validator(
            [](const std::string& s) -> std::string {
                double t = 0;
                const bool number = CLI::detail::lexical_cast(s, t);
                return number && t > 0 && t < 1 ? "" : "tolerance must be in (0, 1)";
            },
            "(0,1)"));
    cmd->add_option("--max-seconds", args->max_seconds, "wall-clock budget")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--threads", args->threads, "worker threads, 0 for all cores")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--method", args->method, "solver")->check(CLI::IsMember(solver_names()));
    cmd->add_flag("--mesh", args->mesh, "include the solved mesh in the result");
    cmd->add_option("--gltf", args->gltf,
                    "also write the solved mesh and sensors as binary glTF (.glb) here");
    cmd->callback([args, &exit_code] { exit_code = run_solve(*args); });
}

}  // namespace radiant::cli
