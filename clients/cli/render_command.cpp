#include "render_command.h"

#include <algorithm>
#include <array>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "atomic_file.h"
#include "exit_codes.h"
#include "local_solve.h"
#include "radiant/picture/room_view.h"
#include "stored_result.h"

namespace radiant::cli {
namespace {

struct RenderArgs {
    std::string scene;
    std::string out;
    std::string result;  ///< a solved result to draw instead of solving
    SolveFlags flags;
    std::optional<std::array<double, 3>> eye, target;
    std::array<double, 3> up{0, 0, 1};
    double fov = 60;
    int width = 800, height = 600;
    double exposure = 0;  ///< cd/m² shown as white; 0 = automatic
    bool falsecolor = false;
    double max_lux = 0;  ///< top of the false-colour scale; 0 = the largest value, rounded up
};

Vec3 vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

/// Scene-unit coordinates from the command line → the metres of the solved mesh.
Vec3 to_metres(const std::array<double, 3>& a, const Scene& scene) {
    return vec(a) * meters_per_unit(scene.units);
}

/// The camera from the arguments; what they leave open comes from `fallback`.
picture::Camera camera_from(const RenderArgs& args, const Scene& scene, picture::Camera fallback) {
    if (args.eye) fallback.eye = to_metres(*args.eye, scene);
    if (args.target) fallback.target = to_metres(*args.target, scene);
    fallback.up = vec(args.up);
    fallback.vertical_fov_degrees = args.fov;
    fallback.width = args.width;
    fallback.height = args.height;
    return fallback;
}

int run_render(const RenderArgs& args) {
    const std::optional<Scene> scene = load_checked_scene(args.scene, args.flags);
    if (!scene) return kExitBadInput;
    // A camera given in full is checked before solving, so a bad one costs no solve.
    if (args.eye && args.target) {
        if (auto problem = picture::camera_problem(camera_from(args, *scene, {}))) {
            std::cerr << "radiant: " << *problem << '\n';
            return kExitBadInput;
        }
    }
    // The solved result to draw: the --result file, or a solve of the scene now.
    std::optional<Result> result;
    if (args.result.empty()) {
        result = solve_locally(*scene, args.flags, true);
        if (const auto code = report_solve(args.scene, *scene, args.flags, *result)) return *code;
        if (!result->mesh) {
            std::cerr << "radiant: the solve returned no mesh to render\n";
            return kExitFailure;
        }
    } else {
        result = load_stored_result(args.result, *scene, true);
        if (!result) return kExitBadInput;
    }
    const picture::Camera camera =
        camera_from(args, *scene, picture::default_camera(*result->mesh));
    try {
        const picture::Image image = picture::draw_view(
            *result, *scene, camera, {args.falsecolor, args.max_lux, args.exposure});
        write_file_atomically(args.out, image.png());
    } catch (const std::invalid_argument& e) {
        std::cerr << "radiant: " << e.what() << '\n';
        return kExitBadInput;
    }
    return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand(
        "render",
        "Solve a scene (or read --result) and write a perspective picture of it as PNG "
        "(--falsecolor: lux)");
    auto args = std::make_shared<RenderArgs>();
    cmd->add_option("scene", args->scene, "radiant-scene/1 JSON file")->required();
    cmd->add_option("--out", args->out, "the PNG file to write")->required();
    add_result_option(*cmd, args->result, add_solve_flags(*cmd, args->flags));
    cmd->add_option("--eye", args->eye,
                    "camera position X Y Z in scene units (default: inside "
                    "the bounding box, near a lower corner)");
    cmd->add_option("--target", args->target, "point looked at, X Y Z in scene units");
    cmd->add_option("--up", args->up, "up direction X Y Z")->capture_default_str();
    cmd->add_option("--fov", args->fov, "vertical field of view, degrees")
        ->check(CLI::Range(1.0, 179.0))
        ->capture_default_str();
    cmd->add_option("--width", args->width, "pixels")
        ->check(CLI::Range(16, 8192))
        ->capture_default_str();
    cmd->add_option("--height", args->height, "pixels")
        ->check(CLI::Range(16, 8192))
        ->capture_default_str();
    cmd->add_option("--exposure", args->exposure,
                    "luminance (cd/m²) shown as white; default: automatic")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--falsecolor", args->falsecolor,
                  "colour by illuminance (lux) with a legend instead of luminance");
    cmd->add_option("--max-lux", args->max_lux, "top of the false-colour scale")
        ->check(CLI::PositiveNumber);
    cmd->callback([args, &exit_code] { exit_code = run_render(*args); });
}

}  // namespace radiant::cli
