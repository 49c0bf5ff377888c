// `render` and `plan` from a result solved before (`--result RESULT.json`): no solve, the
// result's own numbers and mesh.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::cli {

/// Registers `--result RESULT.json` on a command; it excludes the command's `solve_flags`
/// (add_solve_flags), since nothing is solved.
void add_result_option(CLI::App& command, std::string& result_file,
                       const std::vector<CLI::Option*>& solve_flags);

/// Reads `result_file` as a radiant-result/1 document of `scene`. On a problem — unreadable,
/// malformed (`FILE: /json/pointer: message`), failed, of another scene, or without a mesh when
/// `need_mesh` — prints it and gives nothing.
std::optional<Result> load_stored_result(const std::string& result_file, const Scene& scene,
                                         bool need_mesh);

}  // namespace radiant::cli
