// `radiant import MODEL.hbjson [--out SCENE.json]`: convert a Honeybee model to a scene.
#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

/// Registers the subcommand; `exit_code` receives its result when it runs.
void add_import_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
