#include "radiance_peer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <thread>

#include "combined_runs.h"
#include "radiance_export.h"
#include "radiance_run.h"
#include "reference_csv_file.h"

namespace radiant::bench {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A directory name for a scene: its row name without path separators.
std::string dir_name(const std::string& name) {
    std::string out;
    for (const char c : name) out += (c == '/' || c == ' ') ? '_' : c;
    return out;
}

// The surfaces a reference's checks name, and the checks rtrace -I can answer (all but
// `energy`, which needs the absorbed flux of every surface side).
std::set<std::string> checked_surfaces(const nlohmann::json& checks) {
    std::set<std::string> names;
    if (!checks.is_array()) return names;
    for (const auto& c : checks) {
        const std::string what = c.at("what");
        if (what == "surface") names.insert(c.at("surface").get<std::string>());
    }
    return names;
}

ReferenceAnswer measurable(const ReferenceAnswer& reference) {
    ReferenceAnswer out = reference;
    if (!reference.checks.is_array()) return out;
    out.checks = nlohmann::json::array();
    for (const auto& c : reference.checks) {
        const std::string what = c.at("what");
        if (what != "energy") out.checks.push_back(c);
    }
    return out;
}

// Appends surface-points.txt to points.txt as all-points.txt, so one rtrace run (one process
// start, one time) answers both.
bool combine_points(const fs::path& dir) {
    std::ofstream all(dir / "all-points.txt");
    for (const char* part : {"points.txt", "surface-points.txt"}) {
        std::ifstream in(dir / part);
        // Streaming an empty file's buffer would set the output's failbit.
        if (in && in.peek() != std::ifstream::traits_type::eof()) all << in.rdbuf();
    }
    return static_cast<bool>(all);
}

SensorResult sensor_result(const std::string& name, std::vector<double> values) {
    SensorResult s;
    s.name = name;
    s.illuminance = std::move(values);
    if (s.illuminance.empty()) return s;
    const auto [lo, hi] = std::minmax_element(s.illuminance.begin(), s.illuminance.end());
    s.min = *lo;
    s.max = *hi;
    double sum = 0;
    for (const double v : s.illuminance) sum += v;
    s.average = sum / static_cast<double>(s.illuminance.size());
    s.u0 = s.uniformity = s.average > 0 ? s.min / s.average : 0;
    s.ud = s.max > 0 ? s.min / s.max : 0;
    return s;
}

// The rtrace values as the parts of a Result that relative_error() reads.
Result as_result(const radiance::ExportSummary& summary, const std::vector<Rgb>& lux) {
    Result r;
    r.status = SolveStatus::converged;
    for (const radiance::PointRange& range : summary.sensors) {
        std::vector<double> values;
        for (std::size_t i = 0; i < range.count; ++i) {
            values.push_back(radiance::photometric(lux.at(range.first + i)));
        }
        r.sensors.push_back(sensor_result(range.name, std::move(values)));
    }
    // Surface points follow the sensor points in all-points.txt.
    std::vector<Rgb> surface_lux(lux.begin() + static_cast<std::ptrdiff_t>(summary.points),
                                 lux.end());
    for (const radiance::SurfaceSamples& s : summary.surfaces) {
        const auto avg = radiance::surface_average(s, surface_lux);
        SurfaceResult sr;
        sr.name = s.name;
        for (const double w : s.weights_m2) sr.area_m2 += w;
        sr.average_irradiance = avg.irradiance_lux;
        sr.average_radiosity = avg.radiosity_lm_m2;
        r.surfaces.push_back(sr);
    }
    return r;
}

// Lower envelope of a curve: its points in order of time, each with less error than all the
// faster ones.
std::vector<std::pair<double, double>> envelope(const std::vector<BenchRow>& curve) {
    std::vector<std::pair<double, double>> points;
    for (const auto& r : curve) {
        if ((r.status == "converged" || r.status == "stopped" || r.status == "done") &&
            r.seconds > 0 && std::isfinite(r.rms_error) && r.rms_error > 0) {
            points.push_back({r.seconds, r.rms_error});
        }
    }
    std::sort(points.begin(), points.end());
    std::vector<std::pair<double, double>> front;
    for (const auto& p : points) {
        if (front.empty() || p.second < front.back().second) front.push_back(p);
    }
    return front;
}

void wait_for_a_new_second(std::time_t& last) {
    while (std::time(nullptr) == last) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    last = std::time(nullptr);
}

}  // namespace

const std::vector<RadianceSetting>& default_radiance_ladder() {
    static const std::vector<RadianceSetting> ladder{
        "-ab 2 -aa 0 -ad 128 -lw 1e-3 -ds 0.2 -dt 0.05",
        "-ab 3 -aa 0 -ad 256 -lw 1e-3 -ds 0.2 -dt 0.05",
        "-ab 4 -aa 0 -ad 512 -lw 5e-4 -ds 0.1 -dt 0.02",
        "-ab 6 -aa 0 -ad 1024 -lw 2e-4 -ds 0.1 -dt 0.02",
        "-ab 8 -aa 0 -ad 2048 -lw 1e-4 -ds 0.05 -dt 0 -dc 1",
        "-ab 8 -aa 0 -ad 4096 -lw 1e-5 -ds 0.05 -dt 0 -dc 1",
        // The fine end: in rooms of ρ 0.7 eight bounces still miss a few per cent.
        "-ab 16 -lr -16 -aa 0 -ad 4096 -lw 1e-5 -ds 0.05 -dt 0 -dc 1",
    };
    return ladder;
}

std::optional<fs::path> radiance_for_peer(std::ostream& log) {
    auto bin = radiance::find_radiance();
    if (!bin) {
        log << "radiant-bench: RADIANCE (oconv and rtrace) is not on PATH: the RADIANCE peer is "
               "skipped (docs/radiance-peer.md says how to build it)\n";
    }
    return bin;
}

std::vector<BenchRow> run_radiance_peer(const fs::path& radiance, const Scene& scene,
                                        const ReferenceAnswer& reference,
                                        const std::string& row_name, std::size_t triangles,
                                        const PeerOptions& options, std::ostream& log) {
    const fs::path dir = options.work_dir / dir_name(row_name);
    fs::remove_all(dir);
    radiance::ExportOptions export_options;
    const std::set<std::string> surfaces = checked_surfaces(reference.checks);
    if (!surfaces.empty()) {
        export_options.surface_samples = options.surface_samples;
        export_options.sample_surfaces.assign(surfaces.begin(), surfaces.end());
    }
    std::vector<BenchRow> rows;
    BenchRow row;
    row.scene = row_name;
    row.triangles = triangles;
    row.method = "radiance";
    row.tolerance = row.peak_mib = row.error_estimate = kNaN;
    const auto fail = [&](const std::string& why) {
        log << "radiant-bench: RADIANCE on " << row_name << ": " << why << '\n';
        row.status = "failed";
        row.rms_error = row.max_error = kNaN;
        rows.push_back(row);
        return rows;
    };
    const auto written = radiance::write_radiance_scene(scene, dir, export_options);
    if (!written.ok) return fail(written.error);
    if (!combine_points(dir)) return fail("cannot write " + (dir / "all-points.txt").string());
    if (const std::string why = radiance::make_octree(radiance, dir); !why.empty()) {
        return fail(why);
    }
    const ReferenceAnswer scored = measurable(reference);
    if (scored.checks.is_array() && scored.checks.size() < reference.checks.size()) {
        log << "radiant-bench: RADIANCE on " << row_name
            << ": the energy check is not measured (rtrace -I gives irradiance at points)\n";
    }
    if (written.summary.needs_all_shadow_tests) {
        log << "radiant-bench: RADIANCE on " << row_name
            << ": emitters that reflect: every rung runs with -dt 0 (all shadow rays tested)\n";
    }
    for (const RadianceSetting& rung : options.ladder) {
        // rtrace takes the last of repeated options.
        const RadianceSetting setting =
            written.summary.needs_all_shadow_tests ? rung + " -dt 0" : rung;
        row.setting = setting;
        const auto run = radiance::run_rtrace(
            radiance, dir, setting + " -n " + std::to_string(options.threads), "all-points.txt");
        row.seconds = run.seconds;
        if (!run.ok) {
            fail(run.error);
            continue;
        }
        const RelativeError error =
            relative_error(as_result(written.summary, run.irradiance_lux), scored);
        row.status = "done";
        row.rms_error = error.rms;
        row.max_error = error.max;
        rows.push_back(row);
        log << "radiant-bench: RADIANCE " << row_name << " " << setting << ": "
            << fixed(run.seconds, 2) << " s, RMS error " << sci(error.rms) << '\n';
    }
    return rows;
}

void print_peer_table(std::ostream& out, const std::vector<BenchRow>& rows) {
    out << "\nRADIANCE (rtrace -I, wall time of rtrace; errors against the same references):\n\n"
        << "| scene | setting | seconds | rms error | max error | status |\n"
        << "| --- | --- | ---: | ---: | ---: | --- |\n";
    for (const auto& r : rows) {
        if (r.method != "radiance") continue;
        out << "| " << r.scene << " | " << r.setting << " | " << fixed(r.seconds, 3) << " | "
            << sci(r.rms_error) << " | " << sci(r.max_error) << " | " << r.status << " |\n";
    }
}

std::optional<TimeToError> interpolated_time_to_error(const std::vector<BenchRow>& curve,
                                                      double target) {
    const auto front = envelope(curve);
    for (std::size_t i = 0; i < front.size(); ++i) {
        if (front[i].second > target) continue;
        if (i == 0) return TimeToError{front[0].first, true};
        const auto [t0, e0] = front[i - 1];
        const auto [t1, e1] = front[i];
        const double s = (std::log(target) - std::log(e0)) / (std::log(e1) - std::log(e0));
        return TimeToError{std::exp(std::log(t0) + s * (std::log(t1) - std::log(t0))), false};
    }
    return std::nullopt;
}

void print_equal_error_speed(std::ostream& out, const std::vector<BenchRow>& rows,
                             const std::vector<double>& targets) {
    std::map<std::string, std::map<std::string, std::vector<BenchRow>>> curves;
    for (const auto& r : rows) curves[r.scene][r.method].push_back(r);
    out << "\nSpeed at equal error (seconds to reach the RMS error, log-log interpolated on each "
           "curve's lower envelope; ≤: its fastest run is already below; ratio = RADIANCE / "
           "Radiant):\n\n"
        << "| scene | method | target | Radiant s | RADIANCE s | ratio |\n"
        << "| --- | --- | ---: | ---: | ---: | ---: |\n";
    const auto cell = [](const std::optional<TimeToError>& t) {
        if (!t) return std::string("not reached");
        return (t->at_most ? "≤ " : "") + fixed(t->seconds, 3);
    };
    for (const auto& [scene, methods] : curves) {
        const auto peer = methods.find("radiance");
        if (peer == methods.end()) continue;
        for (const auto& [method, curve] : methods) {
            if (method == "radiance") continue;
            for (const double target : targets) {
                const auto ours = interpolated_time_to_error(curve, target);
                const auto theirs = interpolated_time_to_error(peer->second, target);
                std::string ratio = "n/a";
                if (ours && theirs) {
                    ratio = fixed(theirs->seconds / ours->seconds, 2);
                    if (ours->at_most && !theirs->at_most) ratio = "≥ " + ratio;
                    if (theirs->at_most && !ours->at_most) ratio = "≤ " + ratio;
                    if (ours->at_most && theirs->at_most) ratio = "n/a";
                }
                out << "| " << scene << " | " << method << " | " << sci(target) << " | "
                    << cell(ours) << " | " << cell(theirs) << " | " << ratio << " |\n";
            }
        }
    }
}

bool write_radiance_reference(const fs::path& radiance, const Scene& scene, const fs::path& csv,
                              const RadianceReferenceOptions& options, std::ostream& out,
                              std::ostream& log) {
    const fs::path dir = options.work_dir / dir_name(scene.name.empty() ? "scene" : scene.name);
    fs::remove_all(dir);
    const auto written = radiance::write_radiance_scene(scene, dir);
    if (!written.ok || written.summary.sensors.empty()) {
        log << "radiant-bench: cannot convert the scene: "
            << (written.ok ? "it has no sensor set" : written.error) << '\n';
        return false;
    }
    if (const std::string why = radiance::make_octree(radiance, dir); !why.empty()) {
        log << "radiant-bench: " << why << '\n';
        return false;
    }
    const radiance::PointRange& set = written.summary.sensors.front();
    std::vector<std::vector<double>> runs;
    std::time_t last = 0;
    for (int k = 0; k < options.runs; ++k) {
        // -u+ seeds from the clock in seconds: a run that starts in the same second as the one
        // before would repeat it.
        wait_for_a_new_second(last);
        const auto run = radiance::run_rtrace(
            radiance, dir, "-u+ " + options.setting + " -n " + std::to_string(options.threads));
        if (!run.ok) {
            log << "radiant-bench: " << run.error << '\n';
            return false;
        }
        std::vector<double> values;
        for (std::size_t i = 0; i < set.count; ++i) {
            values.push_back(radiance::photometric(run.irradiance_lux.at(set.first + i)));
        }
        out << "radiant-bench: RADIANCE reference run " << k + 1 << " of " << options.runs << ": "
            << fixed(run.seconds, 1) << " s\n";
        runs.push_back(std::move(values));
    }
    const std::size_t n = set.count;
    const CombinedRuns combined = combine_runs(runs, options.median);
    const std::vector<double>& value = combined.value;
    const std::vector<double>& standard_error = combined.standard_error;
    double overall = 0, sq = 0, worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
        overall += value[i] / static_cast<double>(n);
        sq += standard_error[i] * standard_error[i] / static_cast<double>(n);
        worst = std::max(worst, standard_error[i]);
    }
    std::ifstream points_in(dir / "points.txt");
    std::ofstream csv_out(csv);
    // The standard error lets the benchmark tell a row's miss from the reference's own noise;
    // one run has none.
    const bool with_error = runs.size() > 1;
    csv_out << (with_error ? testing::kReferenceCsvHeaderWithError : testing::kReferenceCsvHeader)
            << '\n';
    std::string line;
    for (std::size_t i = 0; i < set.first + n && std::getline(points_in, line); ++i) {
        if (i < set.first) continue;
        double x = 0, y = 0, z = 0;
        std::sscanf(line.c_str(), "%lf %lf %lf", &x, &y, &z);
        char buf[200];
        std::snprintf(buf, sizeof buf, "%.6f,%.6f,%.6f,%.6f", x, y, z, value[i - set.first]);
        csv_out << buf;
        if (with_error) {
            std::snprintf(buf, sizeof buf, ",%.6f", standard_error[i - set.first]);
            csv_out << buf;
        }
        csv_out << '\n';
    }
    if (!csv_out) {
        log << "radiant-bench: cannot write " << csv << '\n';
        return false;
    }
    out << "radiant-bench: wrote " << csv.string() << ": sensor set \"" << set.name << "\", " << n
        << " points, " << (options.median ? "median" : "mean") << " of " << runs.size()
        << " runs of rtrace -I -u+ " << options.setting << "; standard error: RMS "
        << sci(100 * std::sqrt(sq) / overall) << " %, largest " << sci(100 * worst / overall)
        << " % of the mean illuminance (" << sci(overall) << " lx)\n";
    return true;
}

}  // namespace radiant::bench
