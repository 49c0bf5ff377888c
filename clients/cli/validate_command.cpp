#include "validate_command.h"

#include <iostream>
#include <memory>
#include <string>

#include "exit_codes.h"
#include "radiant/proto/scene_json.h"

namespace radiant::cli {

void add_validate_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("validate", "Check a scene; exit 0, or 2 listing its problems");
    auto file = std::make_shared<std::string>();
    cmd->add_option("scene", *file, "radiant-scene/1 JSON file")->required();
    cmd->callback([file, &exit_code] {
        const proto::ParseOutcome outcome = proto::load_scene_file(*file);
        for (const Problem& p : outcome.problems) {
            std::cerr << proto::format_problem(*file, p) << '\n';
        }
        if (outcome.ok()) std::cout << *file << ": ok\n";
        exit_code = outcome.ok() ? kExitOk : kExitBadInput;
    });
}

}  // namespace radiant::cli
