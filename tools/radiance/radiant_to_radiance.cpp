// radiant-to-radiance SCENE.json --out DIR: a radiant-scene/1 document as RADIANCE input
// (scene.rad, points.txt, README). The scene is read and checked by the same reader as the CLI's,
// so a scene Radiant refuses is refused here with the same messages. Exit codes as the CLI's:
// 0 written, 1 could not write, 2 bad input (nothing written).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "radiance_export.h"
#include "radiant/proto/scene_json.h"

int main(int argc, char** argv) {
    CLI::App app{"radiant-to-radiance: a Radiant scene as RADIANCE input for rtrace -I"};
    std::string scene_file, out_dir;
    radiant::radiance::ExportOptions options;
    app.add_option("scene", scene_file, "radiant-scene/1 JSON file")->required();
    app.add_option("--out", out_dir, "directory to write (created)")->required();
    app.add_option("--source-radius", options.source_radius_m,
                   "radius (m) of the sphere or disk standing for a point luminaire")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--surface-samples", options.surface_samples,
                   "also write about N points on each surface (surface-points.txt, "
                   "surface-samples.txt) for surface averages")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--surface", options.sample_surfaces,
                   "sample only these surfaces (repeat or comma-separate)")
        ->delimiter(',');
    app.add_option("--photometric-step", options.photometric_step_deg,
                   "degrees between the C-planes of a photometric luminaire's data file (γ is "
                   "sampled 4 times finer; a table alike in every C-plane, 20 times finer over "
                   "γ alone)")
        ->check(CLI::Range(0.01, 90.0))
        ->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }

    const radiant::proto::ParseOutcome parsed = radiant::proto::load_scene_file(scene_file);
    for (const radiant::Problem& p : parsed.problems) {
        std::cerr << radiant::proto::format_problem(scene_file, p) << '\n';
    }
    if (!parsed.scene) return 2;
    const auto outcome = radiant::radiance::write_radiance_scene(*parsed.scene, out_dir, options);
    if (!outcome.ok) {
        std::cerr << "radiant-to-radiance: " << outcome.error << '\n';
        return 1;
    }
    const auto& s = outcome.summary;
    std::cout << out_dir << ": " << s.materials << " materials, " << s.polygons << " polygons, "
              << s.light_sources << " light sources, " << s.points << " points";
    if (options.surface_samples > 0) std::cout << ", " << s.surface_points << " surface points";
    std::cout << " (" << s.channels << (s.channels == 1 ? " channel)\n" : " channels)\n");
    return 0;
}
