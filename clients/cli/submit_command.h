#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

/// `radiant submit SCENE.json [--wait] [--server URL]`: prints the job id, or with --wait the
/// result document once the job is done.
void add_submit_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
