#include "stored_result.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "radiant/proto/result_reader.h"
#include "radiant/proto/scene_json.h"

namespace radiant::cli {
namespace {

/// A result file may hold a million-triangle mesh; still, a file this large is no result.
constexpr std::uintmax_t kMaxResultBytes = std::uintmax_t{1} << 30;

}  // namespace

void add_result_option(CLI::App& command, std::string& result_file,
                       const std::vector<CLI::Option*>& solve_flags) {
    CLI::Option* result =
        command.add_option("--result", result_file,
                           "draw this radiant-result/1 file of the scene instead of solving it");
    for (CLI::Option* flag : solve_flags) result->excludes(flag);
}

std::optional<Result> load_stored_result(const std::string& result_file, const Scene& scene,
                                         bool need_mesh) {
    std::error_code ec;
    const std::uintmax_t bytes = std::filesystem::file_size(result_file, ec);
    std::ifstream in(result_file, std::ios::binary);
    if (ec || !in) {
        std::cerr << result_file << ": cannot read the file\n";
        return std::nullopt;
    }
    if (bytes > kMaxResultBytes) {
        std::cerr << result_file << ": larger than " << kMaxResultBytes << " bytes\n";
        return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    proto::ResultReadOutcome outcome = proto::read_result(text.str());
    for (const Problem& p : outcome.problems) {
        std::cerr << proto::format_problem(result_file, p) << '\n';
    }
    if (!outcome.result) return std::nullopt;
    const Result& result = *outcome.result;
    if (result.status == SolveStatus::failed) {
        std::cerr << proto::format_problem(result_file,
                                           {"/status", "the solve failed: " + result.error})
                  << '\n';
        return std::nullopt;
    }
    if (result.scene != scene.name) {
        std::cerr << proto::format_problem(result_file,
                                           {"/scene", "a result of scene \"" + result.scene +
                                                          "\", not \"" + scene.name + "\""})
                  << '\n';
        return std::nullopt;
    }
    if (need_mesh && !result.mesh) {
        std::cerr << proto::format_problem(
                         result_file,
                         {"", "no mesh: solve with --mesh (or GET the result with ?include=mesh)"})
                  << '\n';
        return std::nullopt;
    }
    return std::move(outcome.result);
}

}  // namespace radiant::cli
