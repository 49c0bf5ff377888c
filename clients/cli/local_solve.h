// The in-process solve shared by `radiant solve`, `render` and `plan`: load and check a scene
// file, apply the command-line overrides, solve with a progress line on a terminal.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::cli {

/// Overrides of the scene's `settings`; unset ones keep the scene's value.
struct SolveFlags {
    std::optional<double> tolerance;
    std::optional<double> max_seconds;
    std::optional<int> threads;
    std::optional<std::uint64_t> seed;
    std::optional<std::string> method;
    std::optional<double> max_memory_mb;
    bool progress = false;  ///< print every snapshot as a line on stderr
    bool strict = false;    ///< warnings are errors (exit 2), as the scene's settings.strict
};

/// Registers --tolerance, --max-seconds, --threads, --seed, --method, --max-memory-mb,
/// --strict and --progress on a subcommand; returns them.
std::vector<CLI::Option*> add_solve_flags(CLI::App& command, SolveFlags& flags);

/// Loads and checks `scene_file`; on problems prints them (`FILE: /pointer: message`) and gives
/// nothing, so commands can check their own arguments against the scene before solving. With
/// --max-memory-mb, a file too large to read within it is refused before it is read.
std::optional<Scene> load_checked_scene(const std::string& scene_file, const SolveFlags& flags);

/// Solves `scene` in-process with `flags` over its settings; a progress line on a terminal.
Result solve_locally(const Scene& scene, const SolveFlags& flags, bool want_mesh);

/// Prints each warning on stderr (`FILE: /pointer: message [code]`); true when `strict` makes
/// them errors: the command then writes nothing and exits 2.
bool report_warnings(const std::string& scene_file, const std::vector<Warning>& warnings,
                     bool strict);

/// Prints the result's warnings (report_warnings) and, unless they made it a strict refusal,
/// why the solve failed, if it did. Returns the exit code the command ends with when the solve
/// did not succeed, else nothing.
std::optional<int> report_solve(const std::string& scene_file, const Scene& scene,
                                const SolveFlags& flags, const Result& result);

}  // namespace radiant::cli
