// radiant-bench: speed against error. Runs each solver at several tolerances on a suite of
// scenes — the validation scenes (exact answers), the RADIANCE room, a generated box office at
// 1, 4, 16 and 64 times the furniture, a cluttered furnished office (with panels or IES
// downlights) and floors of 4, 16 and 64 such rooms, and any scene file the user names (the
// generated scenes and scene files against a reference solve, see --reference) —
// each case in its own forked child so its peak memory is its own. Prints a Markdown table and
// writes it as Markdown and CSV, plots error against time with gnuplot, and summarises the
// scaling series and the time each method needs to reach a target error. With --export it
// writes the named scenes as radiant-scene/1 files instead. With --peer radiance, RADIANCE
// traces each scene over a ladder of settings for comparison (radiance_peer.h);
// --radiance-reference makes a RADIANCE reference for a scene file.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "bench_scenes.h"
#include "bench_table.h"
#include "isolated_run.h"
#include "office_scene.h"
#include "path_reference.h"
#include "radiance_peer.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"
#include "reference_answer.h"
#include "reference_cache.h"
#include "scene_export.h"

namespace {

namespace fs = std::filesystem;
using namespace radiant;
using namespace radiant::bench;

constexpr const char* kRadianceRoom = "room-s2";
// The validation set's furnace at reflectances near 1, where a factor sum short by δ costs
// ρδ/(1 − ρ): every surface emits E and reflects ρ, so B = E/(1 − ρ) on all of them, exactly.
constexpr const char* kFurnace = "furnace-rho0.9";
const std::vector<double> kHighReflectances{0.99, 0.999};

std::string furnace_name(double reflectance) {
    std::ostringstream name;
    name << "furnace-rho" << reflectance;
    return name.str();
}

// A --scenes item that names a scene file rather than a built-in scene.
bool is_scene_file(const std::string& item) {
    return item.find('/') != std::string::npos || fs::path(item).extension() == ".json";
}

struct BenchScene {
    Scene scene;
    ReferenceAnswer reference;     ///< for generated scenes and scene files, from a reference solve
    bool needs_reference = false;  ///< a generated scene or scene file: see ReferenceSource
};

// Where the per-point reference of a generated scene or a scene file comes from: fills
// `bench.reference` (source and illuminance of its sensor set) or says why not on stderr and
// returns false: a converged solve of the --reference method, or traced paths; both cached.
using ReferenceSource = std::function<bool(BenchScene& bench)>;

// `furnace` (one glowing material on a closed box) with every reflectance `reflectance`.
BenchScene high_reflectance_furnace(const Scene& furnace, double reflectance) {
    BenchScene bench{furnace, {}};
    bench.scene.name = furnace_name(reflectance);
    Material& glow = bench.scene.materials.at(0);
    glow.reflectance = {reflectance, reflectance, reflectance};
    const double radiosity = glow.emission.value().value / (1 - reflectance);
    nlohmann::json checks = nlohmann::json::array();
    for (const Surface& s : bench.scene.surfaces) {
        checks.push_back({{"what", "surface"},
                          {"surface", s.name},
                          {"field", "average_radiosity"},
                          {"value", radiosity}});
    }
    bench.reference = {"exact", checks, "", {}};
    return bench;
}

std::optional<Scene> load(const fs::path& file) {
    auto outcome = proto::load_scene_file(file);
    for (const auto& p : outcome.problems) {
        std::cerr << proto::format_problem(file.string(), p) << '\n';
    }
    return outcome.scene;
}

// "photons 0.24 · gather 0.49 …": seconds per stage, as the table prints them.
std::string stage_summary(const std::vector<StageStats>& stages) {
    std::ostringstream out;
    out.precision(2);
    for (std::size_t i = 0; i < stages.size(); ++i)
        out << (i ? " · " : "") << stages[i].name << ' ' << std::fixed << stages[i].seconds;
    return out.str();
}

// "residual 1.2e-05 · discretisation 0.0031 …": the estimate's non-zero parts, so that a row
// shows which part decides it.
std::string estimate_summary(const ErrorParts& parts) {
    const std::pair<const char*, double> named[] = {
        {"residual", parts.residual},         {"discretisation", parts.discretisation},
        {"gather noise", parts.gather_noise}, {"photon noise", parts.photon_noise},
        {"completion", parts.completion},     {"cross-check", parts.cross_check}};
    std::ostringstream out;
    out.precision(2);
    for (const auto& [name, value] : named) {
        if (value > 0) out << (out.tellp() > 0 ? " · " : "") << name << ' ' << value;
    }
    return out.str();
}

// A solve in a child: the row's fields as JSON (the child's memory and time are its own).
nlohmann::json solve_case(const Scene& scene, const SolveOptions& options,
                          const ReferenceAnswer& reference) {
    const Result result = solve(scene, options);
    const RelativeError error = relative_error(result, reference);
    const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; };
    return {{"status", to_string(result.status)},
            {"error", result.error},
            {"seconds", result.stats.seconds},
            {"rays", result.stats.rays},
            {"elements", result.stats.elements},
            {"links", result.stats.links},
            {"rms", number(error.rms)},
            {"max", number(error.max)},
            {"estimate", number(scored_estimate(result, reference))},
            {"stages", stage_summary(result.stats.stages)},
            {"estimate_parts", estimate_summary(result.stats.error_parts)},
            {"sensor", result.sensors.empty()
                           ? nlohmann::json(nullptr)
                           : nlohmann::json(new_lamp_illuminance(result.sensors[0]))}};
}

double number_or_nan(const nlohmann::json& j) {
    return j.is_number() ? j.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

unsigned watchdog_for(double max_seconds) {
    // The cap stops the solve; meshing and sensors after it get as long again plus a minute.
    return static_cast<unsigned>(std::ceil(2 * max_seconds + 60));
}

// A reference must be the finest solve there is within its limits: converged, or stopped only
// because refinement could go no finer (its estimate, a little above the tolerance, is printed
// with it) — not cut short by the time cap.
bool usable_reference(const nlohmann::json& solve, double max_seconds) {
    const std::string status = solve.at("status");
    return status == "converged" ||
           (status == "stopped" && solve.at("seconds").get<double>() < max_seconds &&
            solve.at("estimate").is_number());
}

// Monte Carlo references sample with their own seed, so that their noise is independent of the
// rows' (seed 1).
constexpr std::uint64_t kReferenceSeed = 1000003;

// A cached reference becomes the scene's, and says so on stderr.
void adopt_reference(BenchScene& bench, std::string source, CachedReference cached) {
    bench.reference.source = std::move(source);
    bench.reference.illuminance = std::move(cached.illuminance);
    bench.reference.error_estimate = cached.error_estimate;
    std::cerr << "radiant-bench: reference of " << bench.scene.name << ": "
              << bench.reference.source << ", " << cached.seconds << " s, error estimate "
              << cached.error_estimate << '\n';
}

// The converged answer of a generated or user's scene: from the cache (one per method), or a
// solve with `method` at `tolerance` (in a child, so its memory does not inflate the later
// cases' peaks).
bool prepare_reference(BenchScene& bench, const std::string& method, double tolerance,
                       double max_seconds, int threads, const ReferenceCache& cache) {
    auto cached = cache.find(bench.scene, tolerance);
    if (!cached) {
        std::cerr << "radiant-bench: computing the reference of " << bench.scene.name << " ("
                  << method << ", tolerance " << tolerance << ")\n";
        SolveOptions options;
        options.method = method;
        options.seed = kReferenceSeed;
        options.tolerance = tolerance;
        options.max_seconds = max_seconds;
        options.threads = threads;
        const auto outcome =
            run_isolated([&] { return solve_case(bench.scene, options, bench.reference); },
                         watchdog_for(max_seconds));
        if (!outcome.value || !usable_reference(*outcome.value, max_seconds)) {
            std::cerr << "radiant-bench: the reference of " << bench.scene.name
                      << " is not usable: "
                      << (outcome.value ? outcome.value->dump() : outcome.failure) << '\n';
            return false;
        }
        const auto& v = *outcome.value;
        cached = CachedReference{v.at("sensor").get<std::vector<double>>(),
                                 v.at("seconds").get<double>(), number_or_nan(v.at("estimate"))};
        std::cerr << "radiant-bench: the reference solve of " << bench.scene.name << " peaked at "
                  << outcome.peak_mib << " MiB\n";
        cache.store(bench.scene, tolerance, *cached);
    }
    std::ostringstream source;
    source << method << " " << tolerance;
    adopt_reference(bench, source.str(), std::move(*cached));
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "radiant-bench: every solver at several tolerances against exact or reference "
        "answers"};
    std::vector<std::string> methods{"monte-carlo", "direct",   "gauss-seidel",
                                     "jacobi",      "shooting", "hierarchical"};
    std::vector<double> tolerances{0.1, 0.03, 0.01};
    std::vector<std::string> only_scenes;
    std::string out_stem = "radiant-bench";
    std::string data_dir = RADIANT_TEST_DATA;
    std::string cache_dir = RADIANT_BENCH_CACHE;
    double max_seconds = 60;
    std::vector<std::string> method_seconds, method_tolerances;
    double reference_tolerance = 0.002;
    double reference_seconds = 3600;
    double target_error = 0.02;
    int threads = 0;
    std::string export_dir;
    std::string reference_name = "monte-carlo";
    std::string downlight = RADIANT_DOWNLIGHT_IES;
    std::string peer;
    std::vector<std::string> radiance_settings;
    std::vector<double> equal_error_targets{0.01, 0.0025};
    std::string radiance_reference;
    RadianceReferenceOptions reference_options;
    std::string path_reference;
    PathReferenceOptions path_options;
    app.add_option("--methods", methods, "solvers to run")->delimiter(',')->capture_default_str();
    app.add_option("--tolerance", tolerances, "tolerances to run (repeat or comma-separate)")
        ->delimiter(',')
        ->capture_default_str();
    app.add_option(
           "--scenes", only_scenes,
           "scenes: names from expected.json, furnace-rho0.99, furnace-rho0.999, "
           "room-s2 (against tests/data/radiance/room-s2.dj1-reference.csv), office-x1 … "
           "office-x64, furnished-office, furnished-office-ies, "
           "furnished-floor-x4, -x16, -x64, the groups validation (all exact scenes and "
           "room-s2), scaling (the box offices), clutter (the two furnished offices) and "
           "clutter-scaling (furnished-office and the floors), or scene files (a path or "
           "NAME.json: its first sensor set against NAME.reference.csv beside it, else against the "
           "reference solve); default: validation "
           "and scaling")
        ->delimiter(',');
    app.add_option("--max-seconds", max_seconds, "time cap of each case")->capture_default_str();
    app.add_option("--method-seconds", method_seconds,
                   "time caps of one method's cases, METHOD=S (repeat or comma-separate), e.g. "
                   "shooting=900; the others keep --max-seconds")
        ->delimiter(',');
    app.add_option("--method-tolerance", method_tolerances,
                   "tolerances of one method's cases, METHOD=T (repeat or comma-separate, e.g. "
                   "shooting=0.3,shooting=0.1); the others keep --tolerance")
        ->delimiter(',');
    app.add_option("--out", out_stem, "writes STEM.md, STEM.csv, STEM.gp and STEM.png")
        ->capture_default_str();
    app.add_option("--reference", reference_name,
                   "where the references of the generated scenes and scene files come from: "
                   "monte-carlo or hierarchical (a converged solve of that method, cached; "
                   "Monte Carlo with a seed of its own), or paths (traced to --path-error, "
                   "cached)")
        ->capture_default_str();
    app.add_option("--reference-tolerance", reference_tolerance,
                   "tolerance of the converged reference of the offices and scene files")
        ->capture_default_str();
    app.add_option("--reference-seconds", reference_seconds, "time cap of a reference solve")
        ->capture_default_str();
    app.add_option("--cache", cache_dir, "where converged references are kept")
        ->capture_default_str();
    app.add_option("--target-error", target_error, "RMS error for the time-to-error summary")
        ->capture_default_str();
    app.add_option("--data", data_dir, "test data directory (tests/data)")->capture_default_str();
    app.add_option("--threads", threads, "worker threads (0: all cores); also rtrace's -n");
    app.add_option("--export", export_dir,
                   "write each of --scenes as DIR/NAME.json (radiant-scene/1) and solve nothing");
    app.add_option("--downlight", downlight, "IES file of furnished-office-ies")
        ->capture_default_str();
    app.add_option("--peer", peer,
                   "also run a peer on every scene: radiance (rtrace -I over a ladder of "
                   "settings; skipped with a note when oconv and rtrace are not on PATH)")
        ->check(CLI::IsMember({"radiance"}));
    app.add_option("--radiance-settings", radiance_settings,
                   "the peer's rtrace settings, one run each (repeat or comma-separate); default: "
                   "the ladder of docs/radiance-peer.md")
        ->delimiter(',');
    app.add_option("--equal-error", equal_error_targets,
                   "RMS errors at which the peer's and Radiant's times are compared")
        ->delimiter(',')
        ->capture_default_str();
    app.add_option("--radiance-reference", radiance_reference,
                   "instead of benchmarking: average --radiance-runs independent RADIANCE runs at "
                   "this scene file's first sensor set and write them to --out (CSV)");
    app.add_option("--radiance-runs", reference_options.runs, "runs of --radiance-reference")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    app.add_flag("--radiance-median", reference_options.median,
                 "--radiance-reference takes the runs' median at each point, not their mean");
    app.add_option("--radiance-reference-settings", reference_options.setting,
                   "rtrace settings of each --radiance-reference run")
        ->capture_default_str();
    app.add_option("--path-reference", path_reference,
                   "instead of benchmarking: trace paths from this scene file's first sensor set "
                   "until --path-error and write them to --out (CSV; see docs/benchmark.md)");
    app.add_option("--path-error", path_options.relative_error,
                   "RMS standard error of --path-reference, as a share of the mean")
        ->check(CLI::Range(1e-5, 0.5))
        ->capture_default_str();
    app.add_option("--path-seed", path_options.seed, "seed of --path-reference")
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    const int peer_threads =
        threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

    // --out of the reference modes names a CSV file, with or without its extension.
    const auto reference_csv_name = [&] {
        return fs::path(out_stem).extension() == ".csv" ? out_stem : out_stem + ".csv";
    };
    if (!radiance_reference.empty()) {
        const auto scene = load(radiance_reference);
        if (!scene) return 2;
        const auto bin = radiance_for_peer(std::cerr);
        if (!bin) return 1;
        const std::string csv = reference_csv_name();
        reference_options.threads = peer_threads;
        reference_options.work_dir = fs::path(csv).replace_extension("").string() + "-radiance";
        return write_radiance_reference(*bin, *scene, csv, reference_options, std::cout, std::cerr)
                   ? 0
                   : 1;
    }
    if (!path_reference.empty()) {
        const auto scene = load(path_reference);
        if (!scene) return 2;
        const std::string csv = reference_csv_name();
        path_options.threads = threads;
        return write_path_reference(*scene, csv, path_options, std::cout, std::cerr) ? 0 : 1;
    }
    std::optional<fs::path> radiance_bin;
    if (peer == "radiance") radiance_bin = radiance_for_peer(std::cout);
    PeerOptions peer_options;
    peer_options.threads = peer_threads;
    peer_options.work_dir = out_stem + "-radiance";
    if (!radiance_settings.empty()) peer_options.ladder = radiance_settings;

    const std::vector<std::string> solvers = solver_names();
    auto known_method = [&](const std::string& m) {
        return std::find(solvers.begin(), solvers.end(), m) != solvers.end();
    };
    for (const auto& m : methods) {
        if (!known_method(m)) {
            std::cerr << "radiant-bench: unknown method " << m << '\n';
            return 2;
        }
    }
    // METHOD=NUMBER items of --method-seconds and --method-tolerance.
    auto per_method = [&](const std::vector<std::string>& items, const char* option,
                          std::map<std::string, std::vector<double>>& out) {
        for (const auto& item : items) {
            const auto eq = item.find('=');
            char* end = nullptr;
            const double value =
                eq == std::string::npos ? 0 : std::strtod(item.c_str() + eq + 1, &end);
            if (eq == std::string::npos || !known_method(item.substr(0, eq)) || end == nullptr ||
                *end != '\0' || !(value > 0)) {
                std::cerr << "radiant-bench: " << option << " wants METHOD=NUMBER, got " << item
                          << '\n';
                return false;
            }
            out[item.substr(0, eq)].push_back(value);
        }
        return true;
    };
    std::map<std::string, std::vector<double>> cap_of_method, tolerances_of_method;
    if (!per_method(method_seconds, "--method-seconds", cap_of_method) ||
        !per_method(method_tolerances, "--method-tolerance", tolerances_of_method)) {
        return 2;
    }
    const fs::path data(data_dir);
    nlohmann::json expected;
    {
        std::ifstream in(data / "scenes" / "expected.json");
        expected = nlohmann::json::parse(in, nullptr, false);
        if (expected.is_discarded() || !expected.is_object()) {
            std::cerr << "radiant-bench: cannot read " << (data / "scenes" / "expected.json")
                      << '\n';
            return 2;
        }
    }
    std::vector<std::string> validation;
    for (auto it = expected.cbegin(); it != expected.cend(); ++it) validation.push_back(it.key());
    for (const double rho : kHighReflectances) validation.push_back(furnace_name(rho));
    validation.push_back(kRadianceRoom);
    const std::vector<std::string>& scaling = office_series();
    const std::map<std::string, std::vector<std::string>> groups{
        {"validation", validation},
        {"scaling", scaling},
        {"clutter", clutter_scenes()},
        {"clutter-scaling", clutter_series()}};

    std::vector<std::string> names;
    std::map<std::string, Scene> scene_files;  // by the --scenes item that named them
    if (only_scenes.empty()) only_scenes = {"validation", "scaling"};
    for (const auto& s : only_scenes) {
        const auto in_group = groups.find(s);
        const auto& group =
            in_group != groups.end() ? in_group->second : std::vector<std::string>{s};
        for (const auto& n : group) {
            if (is_scene_file(n)) {
                if (scene_files.count(n) == 0) {
                    auto scene = load(n);
                    if (!scene) return 2;
                    if (scene->sensors.empty()) {
                        std::cerr << "radiant-bench: " << n
                                  << " has no sensors: its errors are measured on its first "
                                     "sensor set\n";
                        return 2;
                    }
                    scene_files.emplace(n, std::move(*scene));
                    names.push_back(n);
                }
                continue;
            }
            const bool known =
                std::find(validation.begin(), validation.end(), n) != validation.end() ||
                is_generated_scene(n);
            if (!known) {
                std::cerr << "radiant-bench: unknown scene " << n << '\n';
                return 2;
            }
            if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
        }
    }

    // The scene and, where it is known beforehand, the answer of a --scenes item; nullopt (with
    // a message) when a file cannot be read.
    const auto bench_scene = [&](const std::string& name) -> std::optional<BenchScene> {
        BenchScene bench;
        if (const auto file = scene_files.find(name); file != scene_files.end()) {
            bench.scene = file->second;
            // A reference beside the file is independent of Radiant's solvers, so it is
            // preferred to a reference solve: RADIANCE's (--radiance-reference), else traced
            // paths' (--path-reference) where RADIANCE reads the room dark.
            const fs::path radiance = fs::path(name).replace_extension(".reference.csv");
            const fs::path paths = fs::path(name).replace_extension(".path-reference.csv");
            const bool by_radiance = fs::exists(radiance);
            const fs::path beside = by_radiance ? radiance : paths;
            if (!fs::exists(beside)) {
                bench.needs_reference = true;
            } else {
                const SensorSet& first = bench.scene.sensors.at(0);
                bench.reference =
                    read_reference_csv(beside,
                                       (by_radiance ? "RADIANCE (" : "traced paths (") +
                                           beside.filename().string() + ")",
                                       first.name);
                if (bench.reference.illuminance.size() != first.points.size()) {
                    std::cerr << "radiant-bench: " << beside.string() << " has "
                              << bench.reference.illuminance.size() << " values, but sensor set \""
                              << first.name << "\" of " << name << " has " << first.points.size()
                              << " points\n";
                    return std::nullopt;
                }
                std::cerr << "radiant-bench: reference of " << bench.scene.name << ": "
                          << bench.reference.source << ", " << first.points.size() << " points\n";
            }
        } else if (name == kRadianceRoom) {
            const auto scene = load(data / "radiance" / "room-s2.json");
            if (!scene) return std::nullopt;
            bench.scene = *scene;
            // The -dj 1 reference: the shared one's indirect part is 0.2 % low (see
            // tests/data/radiance/README.md), more than a tight estimate at 0.01.
            bench.reference = read_reference_csv(data / "radiance" / "room-s2.dj1-reference.csv",
                                                 "RADIANCE (-dj 1)", "workplane");
        } else if (const auto rho = std::find_if(kHighReflectances.begin(), kHighReflectances.end(),
                                                 [&](double r) { return furnace_name(r) == name; });
                   rho != kHighReflectances.end()) {
            const auto furnace = load(data / "scenes" / (std::string(kFurnace) + ".json"));
            if (!furnace) return std::nullopt;
            bench = high_reflectance_furnace(*furnace, *rho);
        } else if (expected.contains(name)) {
            const auto scene = load(data / "scenes" / (name + ".json"));
            if (!scene) return std::nullopt;
            bench.scene = *scene;
            bench.reference = {"exact", expected.at(name), "", {}};
        } else {
            std::string why;
            auto scene = generated_scene(name, downlight, why);
            if (!scene) {
                std::cerr << "radiant-bench: " << why << '\n';
                return std::nullopt;
            }
            bench.scene = std::move(*scene);
            bench.needs_reference = true;
        }
        if (bench.needs_reference) bench.reference.sensor = bench.scene.sensors.at(0).name;
        return bench;
    };

    if (!export_dir.empty()) {
        std::error_code ec;
        fs::create_directories(export_dir, ec);
        for (const auto& name : names) {
            const auto bench = bench_scene(name);
            if (!bench) return 2;
            const std::string stem =
                bench->scene.name.empty() ? fs::path(name).stem().string() : bench->scene.name;
            const fs::path file = fs::path(export_dir) / (stem + ".json");
            std::ofstream out(file);
            out << scene_document(bench->scene);
            if (!out.flush()) {
                std::cerr << "radiant-bench: cannot write " << file << '\n';
                return 2;
            }
            std::size_t points = 0;
            for (const SensorSet& set : bench->scene.sensors) points += set.points.size();
            std::cout << file.string() << ": " << input_triangles(bench->scene) << " triangles, "
                      << points << " sensor points\n";
        }
        return 0;
    }

    const ReferenceCache cache{fs::path(cache_dir) / reference_name};
    const auto converged_solve = [&](BenchScene& bench) {
        return prepare_reference(bench, reference_name, reference_tolerance, reference_seconds,
                                 threads, cache);
    };
    // Traced paths (as --path-reference writes them), cached as the solves are: keyed by
    // --path-error, their error estimate the points' RMS standard error over their mean.
    const auto traced_paths = [&](BenchScene& bench) {
        auto cached = cache.find(bench.scene, path_options.relative_error);
        if (!cached) {
            std::cerr << "radiant-bench: tracing the reference of " << bench.scene.name
                      << " (paths to " << path_options.relative_error << " of the mean)\n";
            // Named by the scene, so that two benchmarks sharing a cache do not write one file.
            const fs::path csv =
                fs::path(cache_dir) / reference_name /
                ("tracing-" + std::to_string(scene_fingerprint(bench.scene)) + ".csv");
            fs::create_directories(csv.parent_path());
            path_options.threads = threads;
            const auto start = std::chrono::steady_clock::now();
            if (!write_path_reference(bench.scene, csv, path_options, std::cerr, std::cerr))
                return false;
            const ReferenceAnswer traced = read_reference_csv(csv, "", bench.reference.sensor);
            cached = CachedReference{
                traced.illuminance,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                traced.error_estimate};
            cache.store(bench.scene, path_options.relative_error, *cached);
            fs::remove(csv);
        }
        adopt_reference(bench, "traced paths", std::move(*cached));
        return true;
    };
    const std::map<std::string, ReferenceSource> reference_sources{
        {"hierarchical", converged_solve},
        {"monte-carlo", converged_solve},
        {"paths", traced_paths}};
    const auto source = reference_sources.find(reference_name);
    if (source == reference_sources.end()) {
        std::cerr << "radiant-bench: unknown reference source " << reference_name << '\n';
        return 2;
    }

    std::ofstream markdown(out_stem + ".md"), csv(out_stem + ".csv");
    if (!markdown || !csv) {
        std::cerr << "radiant-bench: cannot write " << out_stem << ".md / .csv\n";
        return 2;
    }
    print_markdown_header(std::cout);
    print_markdown_header(markdown);
    print_csv_header(csv);

    std::vector<BenchRow> rows;
    bool all_ok = true;
    for (const auto& name : names) {
        auto made = bench_scene(name);
        if (!made) return 2;
        BenchScene& bench = *made;
        const std::string row_name =
            scene_files.count(name) && !bench.scene.name.empty() ? bench.scene.name : name;
        if (bench.needs_reference && !source->second(bench)) {
            all_ok = false;
            continue;
        }
        const std::size_t triangles = input_triangles(bench.scene);
        for (const auto& method : methods) {
            const auto cap = cap_of_method.find(method);
            const double seconds = cap != cap_of_method.end() ? cap->second.back() : max_seconds;
            const auto own = tolerances_of_method.find(method);
            for (const double tol : own != tolerances_of_method.end() ? own->second : tolerances) {
                SolveOptions options = options_from(bench.scene.settings);
                options.method = method;
                options.tolerance = tol;
                options.max_seconds = seconds;
                options.threads = threads;
                const auto outcome =
                    run_isolated([&] { return solve_case(bench.scene, options, bench.reference); },
                                 watchdog_for(seconds));
                BenchRow row;
                row.scene = row_name;
                row.triangles = triangles;
                row.method = method;
                row.tolerance = tol;
                row.peak_mib = outcome.peak_mib;
                row.reference_error = bench.reference.error_estimate;
                if (outcome.value) {
                    const auto& v = *outcome.value;
                    row.status = v.at("status");
                    row.seconds = v.at("seconds");
                    row.rays = v.at("rays");
                    row.elements = v.at("elements");
                    row.links = v.at("links");
                    row.rms_error = number_or_nan(v.at("rms"));
                    row.max_error = number_or_nan(v.at("max"));
                    row.error_estimate = number_or_nan(v.at("estimate"));
                    row.stages = v.at("stages");
                    row.estimate_parts = v.at("estimate_parts");
                    if (row.status == "failed") {
                        std::cerr << name << " / " << method << ": "
                                  << v.at("error").get<std::string>() << '\n';
                    }
                } else {
                    row.status = "crashed";
                    row.rms_error = row.max_error = row.error_estimate = std::nan("");
                    std::cerr << name << " / " << method << ": " << outcome.failure << '\n';
                    all_ok = false;
                }
                print_markdown_row(std::cout, row);
                std::cout << std::flush;
                print_markdown_row(markdown, row);
                print_csv_row(csv, row);
                rows.push_back(row);
                // A refusal (e.g. a dense solver on too many polygons) does not depend on the
                // tolerance: the other tolerances would only repeat it.
                if (row.status == "failed") break;
            }
        }
        if (radiance_bin) {
            for (const BenchRow& row :
                 run_radiance_peer(*radiance_bin, bench.scene, bench.reference, row_name, triangles,
                                   peer_options, std::cerr)) {
                print_markdown_row(std::cout, row);
                std::cout << std::flush;
                print_markdown_row(markdown, row);
                print_csv_row(csv, row);
                rows.push_back(row);
            }
        }
    }

    std::ostringstream summary;
    print_time_to_error(summary, rows, target_error);
    for (const auto* scenes : {&scaling, &clutter_series()}) {
        std::vector<std::string> series;
        for (const auto& n : *scenes) {
            if (std::find(names.begin(), names.end(), n) != names.end()) series.push_back(n);
        }
        if (series.size() >= 2) print_scaling(summary, rows, series);
    }
    print_estimate_misses(summary, rows);
    if (radiance_bin) {
        print_peer_table(summary, rows);
        print_equal_error_speed(summary, rows, equal_error_targets);
    }
    std::cout << summary.str();
    markdown << summary.str();
    plot_error_against_time(rows, out_stem, std::cerr);
    return all_ok ? 0 : 1;
}
