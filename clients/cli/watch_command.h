#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

/// `radiant watch ID`: a progress bar from the job's event stream until it finishes.
void add_watch_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
