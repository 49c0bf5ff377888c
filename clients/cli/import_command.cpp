#include "import_command.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "atomic_file.h"
#include "exit_codes.h"
#include "radiant/proto/honeybee.h"
#include "radiant/proto/scene_json.h"

namespace radiant::cli {
namespace {

struct ImportArgs {
    std::string model;
    std::string out;
};

int run_import(const ImportArgs& args) {
    auto refuse = [&](const Problem& p) {
        std::cerr << proto::format_problem(args.model, p) << '\n';
        return kExitBadInput;
    };
    std::error_code ec;
    const auto size = std::filesystem::file_size(args.model, ec);
    if (ec) return refuse({"", "cannot read the file: " + ec.message()});
    const std::size_t limit = proto::ParseLimits{}.max_bytes;
    if (size > limit) {
        return refuse({"", "the file is " + std::to_string(size) + " bytes, over the limit of " +
                               std::to_string(limit)});
    }
    std::ifstream in(args.model, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const proto::HoneybeeOutcome outcome = proto::honeybee_to_scene(text.str());
    for (const Problem& p : outcome.problems) refuse(p);
    if (!outcome.scene) return kExitBadInput;
    const std::string scene = outcome.scene->dump(1) + "\n";
    if (args.out.empty()) {
        std::cout << scene << std::flush;
    } else {
        write_file_atomically(args.out, scene);
    }
    return kExitOk;
}

}  // namespace

void add_import_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand(
        "import", "Convert a Honeybee model (HBJSON) to a radiant-scene/1 document on stdout");
    auto args = std::make_shared<ImportArgs>();
    cmd->add_option("model", args->model, "Honeybee model JSON file (.hbjson)")->required();
    cmd->add_option("--out", args->out, "write the scene here (atomically) instead of stdout");
    cmd->callback([args, &exit_code] { exit_code = run_import(*args); });
}

}  // namespace radiant::cli
