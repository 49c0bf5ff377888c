#include "plan_command.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>

#include "atomic_file.h"
#include "exit_codes.h"
#include "local_solve.h"
#include "radiant/picture/sensor_plan.h"
#include "radiant/proto/scene_json.h"
#include "stored_result.h"
#include "task_area_marks.h"

namespace radiant::cli {
namespace {

struct PlanArgs {
    std::string scene;
    std::string out;
    std::string sensors;  ///< the set to draw; empty = the first
    std::string result;   ///< a solved result to draw instead of solving
    SolveFlags flags;
    double max_lux = 0;
    int size = 800;
};

int run_plan(const PlanArgs& args) {
    const std::optional<Scene> scene = load_checked_scene(args.scene, args.flags);
    if (!scene) return kExitBadInput;
    // The set is looked up before solving, so a wrong name costs no solve.
    const std::vector<SensorSet>& sets = scene->sensors;
    const auto set = std::find_if(sets.begin(), sets.end(), [&](const SensorSet& s) {
        return args.sensors.empty() || s.name == args.sensors;
    });
    if (set == sets.end()) {
        std::cerr << args.scene << ": "
                  << (args.sensors.empty() ? "the scene has no sensors"
                                           : "no sensor set named \"" + args.sensors + "\"")
                  << '\n';
        return kExitBadInput;
    }
    const auto index = static_cast<std::size_t>(set - sets.begin());
    std::optional<Result> result;
    if (args.result.empty()) {
        result = solve_locally(*scene, args.flags, false);
        if (const auto code = report_solve(args.scene, *scene, args.flags, *result)) return *code;
    } else {
        result = load_stored_result(args.result, *scene, false);
        if (!result) return kExitBadInput;
        if (index >= result->sensors.size() || result->sensors[index].name != set->name ||
            result->sensors[index].points.empty()) {
            std::cerr << proto::format_problem(
                             args.result, {"/sensors", "no points of sensor set \"" + set->name +
                                                           "\" in the result"})
                      << '\n';
            return kExitBadInput;
        }
    }
    picture::SensorPlan plan =
        picture::sensor_plan_of(result->scene, result->sensors[index], args.max_lux);
    add_task_area_marks(*scene, *result, index, plan);
    write_file_atomically(args.out, picture::draw_sensor_plan(plan, args.size).png());
    return kExitOk;
}

}  // namespace

void add_plan_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand(
        "plan",
        "Solve a scene (or read --result) and write a top-down false-colour lux map of a sensor "
        "set (PNG)");
    auto args = std::make_shared<PlanArgs>();
    cmd->add_option("scene", args->scene, "radiant-scene/1 JSON file")->required();
    cmd->add_option("--out", args->out, "the PNG file to write")->required();
    cmd->add_option("--sensors", args->sensors, "name of the sensor set (default: the first)");
    add_result_option(*cmd, args->result, add_solve_flags(*cmd, args->flags));
    cmd->add_option("--max-lux", args->max_lux, "top of the colour scale (default: automatic)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--size", args->size, "pixels along the longer side of the map")
        ->check(CLI::Range(100, 8192))
        ->capture_default_str();
    cmd->callback([args, &exit_code] { exit_code = run_plan(*args); });
}

}  // namespace radiant::cli
