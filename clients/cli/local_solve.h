// The in-process solve shared by `radiant solve`, `render` and `plan`: load and check a scene
// file, apply the command-line overrides, solve with a progress line on a terminal.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::cli {

/// Overrides of the scene's `settings`; unset ones keep the scene's value.
struct SolveFlags {
    std::optional<double> tolerance;
    std::optional<double> max_seconds;
    std::optional<int> threads;
    std::optional<std::string> method;
};

/// Registers --tolerance, --max-seconds, --threads and --method on a subcommand.
void add_solve_flags(CLI::App& command, SolveFlags& flags);

struct LocalSolve {
    int exit_code = 0;  ///< kExitOk, or kExitBadInput after the scene's problems went to stderr
    std::optional<Scene> scene;
    Result result;
};

/// Loads `scene_file`, prints its problems (exit 2) or solves it. A failed solve is in `result`.
LocalSolve solve_scene_file(const std::string& scene_file, const SolveFlags& flags, bool want_mesh);

}  // namespace radiant::cli
