#include "validate_command.h"

#include <iostream>
#include <memory>
#include <string>

#include "exit_codes.h"
#include "local_solve.h"
#include "radiant/proto/scene_json.h"
#include "radiant/warnings.h"

namespace radiant::cli {
namespace {

struct ValidateArgs {
    std::string scene;
    bool strict = false;
};

int run_validate(const ValidateArgs& args) {
    const proto::ParseOutcome outcome = proto::load_scene_file(args.scene);
    for (const Problem& p : outcome.problems) {
        std::cerr << proto::format_problem(args.scene, p) << '\n';
    }
    if (!outcome.ok()) return kExitBadInput;
    // A valid scene may still be a mistake: the modelling checks a solve starts with.
    const Scene& scene = *outcome.scene;
    if (report_warnings(args.scene, check_modelling(scene), args.strict || scene.settings.strict))
        return kExitBadInput;
    std::cout << args.scene << ": ok\n";
    return kExitOk;
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand(
        "validate", "Check a scene; exit 0, or 2 listing its problems (warnings go to stderr)");
    auto args = std::make_shared<ValidateArgs>();
    cmd->add_option("scene", args->scene, "radiant-scene/1 JSON file")->required();
    cmd->add_flag("--strict", args->strict, "warnings are errors: exit 2 when there are any");
    cmd->callback([args, &exit_code] { exit_code = run_validate(*args); });
}

}  // namespace radiant::cli
