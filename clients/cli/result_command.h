#pragma once

#include <CLI/CLI.hpp>

namespace radiant::cli {

/// `radiant result ID`: the job's radiant-result/1 document.
void add_result_command(CLI::App& app, int& exit_code);

}  // namespace radiant::cli
