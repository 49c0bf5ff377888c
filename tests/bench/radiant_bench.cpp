// radiant-bench: runs each solver on each validation scene and prints how fast and how accurate
// it is, as a Markdown table (and optionally CSV).
//
// Scenes: tests/data/scenes/<name>.json for every entry of expected.json, plus
// tests/data/radiance/room-s2.json against its RADIANCE reference CSV. "True error" is the largest
// relative error over a scene's checks: surface values |got/want − 1|; energy balance
// |absorbed/emitted − 1|; sensor-max checks the ratio dark max / lit mean itself (exact answer 0);
// room-s2 the normalised RMS error sqrt(mean((E − Eref)²)) / mean(Eref) of the 81 work-plane
// points.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace {

namespace fs = std::filesystem;
using radiant::Result;

constexpr const char* kRoomScene = "room-s2";

struct Row {
    std::string scene, method, status, worst;
    double tolerance = 0, seconds = 0, error_estimate = 0, true_error = 0;
    std::uint64_t rays = 0;
    std::size_t patches = 0, iterations = 0;
};

const radiant::SurfaceResult* find_surface(const Result& r, const std::string& name) {
    for (const auto& s : r.surfaces) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

const radiant::SensorResult* find_sensor(const Result& r, const std::string& name) {
    for (const auto& s : r.sensors) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct TrueError {
    double value = 0;
    std::string worst;  ///< which check gave `value`
};

// Largest error over a scene's expected.json checks; NaN when a check cannot be evaluated.
TrueError checks_error(const Result& result, const nlohmann::json& checks) {
    TrueError out;
    for (const auto& check : checks) {
        const std::string what = check.at("what");
        double err = kNaN;
        std::string label = what;
        if (what == "surface") {
            label = check.at("surface").get<std::string>() + " " +
                    (check.at("field") == "average_irradiance" ? "H" : "B");
            if (const auto* s = find_surface(result, check.at("surface"))) {
                const double got = check.at("field") == "average_irradiance" ? s->average_irradiance
                                                                             : s->average_radiosity;
                err = std::abs(got / check.at("value").get<double>() - 1.0);
            }
        } else if (what == "energy") {
            err = std::abs(result.stats.absorbed_flux_lm / result.stats.emitted_flux_lm - 1.0);
        } else if (what == "sensor-max") {
            label = check.at("sensor").get<std::string>() + " max/lit";
            const auto* dark = find_sensor(result, check.at("sensor"));
            const auto* lit = find_sensor(result, check.at("max_relative_to"));
            if (dark && lit && lit->average > 0) err = std::abs(dark->max / lit->average);
        }
        if (!(err <= std::numeric_limits<double>::max())) return {kNaN, label};
        if (err >= out.value) out = {err, label};
    }
    return out;
}

std::vector<double> read_reference(const fs::path& csv) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);  // header x,y,z,irradiance
    std::vector<double> values;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const auto comma = line.rfind(',');
        values.push_back(std::stod(line.substr(comma + 1)));
    }
    return values;
}

TrueError room_error(const Result& result, const std::vector<double>& reference) {
    const auto* plane = find_sensor(result, "workplane");
    if (!plane || plane->illuminance.size() != reference.size() || reference.empty()) {
        return {kNaN, "workplane nRMS"};
    }
    double sq = 0, mean = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const double d = plane->illuminance[i] - reference[i];
        sq += d * d;
        mean += reference[i];
    }
    const double n = static_cast<double>(reference.size());
    return {std::sqrt(sq / n) / (mean / n), "workplane nRMS"};
}

std::string fixed(double v, int digits) {
    if (std::isnan(v)) return "n/a";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string sci(double v) {
    if (std::isnan(v)) return "n/a";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

std::vector<std::string> cells(const Row& r) {
    return {r.scene,
            r.method,
            sci(r.tolerance),
            fixed(r.seconds, 3),
            std::to_string(r.rays),
            std::to_string(r.patches),
            std::to_string(r.iterations),
            sci(r.error_estimate),
            sci(r.true_error),
            r.worst,
            r.status};
}

const std::vector<std::string> kHeader{"scene",      "method",      "tolerance",  "seconds",
                                       "rays",       "patches",     "iterations", "error estimate",
                                       "true error", "worst check", "status"};

void print_markdown(std::ostream& out, const std::vector<std::string>& row) {
    out << '|';
    for (const auto& c : row) out << ' ' << c << " |";
    out << '\n';
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"radiant-bench: every solver on every validation scene"};
    std::vector<std::string> methods{"direct", "jacobi", "gauss-seidel", "shooting"};
    std::vector<double> tolerances;
    std::vector<std::string> only_scenes;
    std::string csv_path;
    std::string data_dir = RADIANT_TEST_DATA;
    int threads = 0;
    app.add_option("--methods", methods, "solvers to run (default: all four)")->delimiter(',');
    app.add_option("--tolerance", tolerances,
                   "tolerance(s) to run; may be repeated (default: each scene's own)");
    app.add_option("--scenes", only_scenes,
                   "only these scenes (names as in expected.json, or "
                   "room-s2)")
        ->delimiter(',');
    app.add_option("--csv", csv_path, "also write the rows as CSV to FILE");
    app.add_option("--data", data_dir, "test data directory (tests/data)");
    app.add_option("--threads", threads, "worker threads (0: all cores)");
    CLI11_PARSE(app, argc, argv);

    const fs::path data(data_dir);
    nlohmann::json expected;
    try {
        std::ifstream in(data / "scenes" / "expected.json");
        expected = nlohmann::json::parse(in);
    } catch (const std::exception& e) {
        std::cerr << "radiant-bench: cannot read expected.json: " << e.what() << '\n';
        return 2;
    }
    std::vector<std::string> scenes;
    for (auto it = expected.cbegin(); it != expected.cend(); ++it) scenes.push_back(it.key());
    scenes.push_back(kRoomScene);
    if (!only_scenes.empty()) {
        for (const auto& s : only_scenes) {
            if (std::find(scenes.begin(), scenes.end(), s) == scenes.end()) {
                std::cerr << "radiant-bench: unknown scene " << s << '\n';
                return 2;
            }
        }
        scenes = only_scenes;
    }
    for (const auto& m : methods) {
        const auto& names = radiant::solver_names();
        if (std::find(names.begin(), names.end(), m) == names.end()) {
            std::cerr << "radiant-bench: unknown method " << m << '\n';
            return 2;
        }
    }

    std::ofstream csv;
    if (!csv_path.empty()) {
        csv.open(csv_path);
        if (!csv) {
            std::cerr << "radiant-bench: cannot write " << csv_path << '\n';
            return 2;
        }
        for (std::size_t i = 0; i < kHeader.size(); ++i) csv << (i ? "," : "") << kHeader[i];
        csv << '\n';
    }

    print_markdown(std::cout, kHeader);
    std::cout << '|';
    for (std::size_t i = 0; i < kHeader.size(); ++i) {
        std::cout << (i < 2 || i + 2 >= kHeader.size() ? " --- |" : " ---: |");
    }
    std::cout << '\n' << std::flush;

    bool all_ok = true;
    for (const auto& name : scenes) {
        const bool room = name == kRoomScene;
        const fs::path file =
            room ? data / "radiance" / "room-s2.json" : data / "scenes" / (name + ".json");
        const auto outcome = radiant::proto::load_scene_file(file);
        if (!outcome.ok()) {
            for (const auto& p : outcome.problems) {
                std::cerr << radiant::proto::format_problem(file.string(), p) << '\n';
            }
            all_ok = false;
            continue;
        }
        const radiant::Scene& scene = *outcome.scene;
        const std::vector<double> reference =
            room ? read_reference(data / "radiance" / "room-s2.reference.csv")
                 : std::vector<double>{};
        const std::vector<double> tols =
            tolerances.empty() ? std::vector<double>{scene.settings.tolerance} : tolerances;
        for (const double tol : tols) {
            for (const auto& method : methods) {
                radiant::SolveOptions options = radiant::options_from(scene.settings);
                options.method = method;
                options.tolerance = tol;
                options.threads = threads;
                const Result result = radiant::solve(scene, options);
                Row row;
                row.scene = name;
                row.method = method;
                row.status = radiant::to_string(result.status);
                row.tolerance = tol;
                row.seconds = result.stats.seconds;
                row.rays = result.stats.rays;
                row.patches = result.stats.patches;
                row.iterations = result.stats.iterations;
                row.error_estimate = result.stats.error_estimate;
                if (result.status == radiant::SolveStatus::failed) {
                    std::cerr << name << " / " << method << ": " << result.error << '\n';
                    row.true_error = kNaN;
                    all_ok = false;
                } else {
                    const TrueError e =
                        room ? room_error(result, reference) : checks_error(result, expected[name]);
                    row.true_error = e.value;
                    row.worst = e.worst;
                }
                const auto c = cells(row);
                print_markdown(std::cout, c);
                std::cout << std::flush;
                if (csv) {
                    for (std::size_t i = 0; i < c.size(); ++i) csv << (i ? "," : "") << c[i];
                    csv << '\n';
                }
            }
        }
    }
    return all_ok ? 0 : 1;
}
