// `radiant status ID` and `radiant result ID`: one GET against radiantd, the JSON printed pretty.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace radiant::cli {

/// Adds subcommand `name` that prints GET /v1/jobs/{id}{suffix} (pretty JSON, like `solve`).
void add_job_document_command(CLI::App& app, int& exit_code, const std::string& name,
                              const std::string& description, const std::string& suffix);

}  // namespace radiant::cli
