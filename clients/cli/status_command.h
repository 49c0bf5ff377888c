#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

/// `radiant status ID`: the job's state as JSON.
void add_status_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
