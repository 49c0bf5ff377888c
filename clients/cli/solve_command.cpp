#include "solve_command.h"

#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "atomic_file.h"
#include "exit_codes.h"
#include "local_solve.h"
#include "radiant/proto/result_gltf.h"
#include "radiant/proto/result_json.h"
#include "radiant/proto/sensors_csv.h"

namespace radiant::cli {
namespace {

struct SolveArgs {
    std::string scene;
    std::string out;
    std::string gltf;
    std::string csv;
    SolveFlags flags;
    bool mesh = false;
    std::optional<int> digits;  ///< overrides the scene's settings.digits
};

int run_solve(const SolveArgs& args) {
    // Before the solve, so that a refused output costs nothing.
    for (const std::string& path : {args.out, args.gltf}) {
        if (!path.empty()) check_output_path(path);
    }
    const std::optional<Scene> scene = load_checked_scene(args.scene, args.flags);
    if (!scene) return kExitBadInput;
    Result result = solve_locally(*scene, args.flags, args.mesh || !args.gltf.empty());
    // A strict refusal writes nothing; a failed solve still writes its result document.
    const std::optional<int> unsuccessful = report_solve(args.scene, *scene, args.flags, result);
    if (unsuccessful == kExitBadInput) return kExitBadInput;
    if (!args.gltf.empty() && result.status != SolveStatus::failed) {
        write_file_atomically(args.gltf, proto::result_to_glb(result, *scene));
    }
    if (!args.mesh) result.mesh.reset();  // requested for the glTF only
    const int digits = args.digits.value_or(scene->settings.digits);
    if (!args.csv.empty() && result.status != SolveStatus::failed) {
        write_file_atomically(args.csv, proto::sensors_csv(result.sensors, digits));
    }
    const std::string text = proto::result_to_json(result, digits).dump(2) + "\n";
    if (args.out.empty()) {
        std::cout << text << std::flush;
    } else {
        write_file_atomically(args.out, text);
    }
    return unsuccessful.value_or(kExitOk);
}

}  // namespace

void add_solve_command(CLI::App& app, int& exit_code) {
    auto* cmd =
        app.add_subcommand("solve", "Solve a scene; the result JSON goes to stdout or --out");
    auto args = std::make_shared<SolveArgs>();
    cmd->add_option("scene", args->scene, "radiant-scene/1 JSON file")->required();
    cmd->add_option("--out", args->out, "write the result here (atomically) instead of stdout");
    add_solve_flags(*cmd, args->flags);
    cmd->add_flag("--mesh", args->mesh, "include the solved mesh in the result");
    cmd->add_option("--gltf", args->gltf,
                    "also write the solved mesh and sensors as binary glTF (.glb) here");
    cmd->add_option("--csv", args->csv,
                    "also write every sensor point (set, index, x, y, z, nx, ny, nz, lux) as CSV "
                    "here");
    cmd->add_option("--digits", args->digits,
                    "significant digits of the result's values (17: unrounded; default: the "
                    "scene's settings.digits, else 4)")
        ->check(CLI::Range(1, 17));
    cmd->callback([args, &exit_code] { exit_code = run_solve(*args); });
}

}  // namespace radiant::cli
