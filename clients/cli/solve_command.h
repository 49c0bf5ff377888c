// `radiant solve SCENE.json [--out RESULT.json] [flags]`: solve one scene in-process.
#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

/// Registers the subcommand; `exit_code` receives its result when it runs.
void add_solve_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
