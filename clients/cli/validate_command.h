// `radiant validate SCENE.json`: check a scene and list its problems.
#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

/// Registers the subcommand; `exit_code` receives its result when it runs.
void add_validate_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
