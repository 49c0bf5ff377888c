#include "bench_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <utility>

namespace radiant::bench {

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

namespace {

// A peer's runs ("done") have no convergence of their own: each is one setting's answer.
bool usable(const BenchRow& r) {
    return (r.status == "converged" || r.status == "stopped" || r.status == "done") &&
           std::isfinite(r.rms_error) && r.seconds > 0;
}

struct Fit {
    double exponent = std::nan("");
    std::size_t points = 0;
};

// Least-squares slope of log y against log x.
Fit log_log_slope(const std::vector<std::pair<double, double>>& xy) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    std::size_t n = 0;
    for (const auto& [x, y] : xy) {
        if (!(x > 0 && y > 0)) continue;
        const double lx = std::log(x), ly = std::log(y);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        ++n;
    }
    Fit fit;
    fit.points = n;
    const double nn = static_cast<double>(n);
    const double denominator = nn * sxx - sx * sx;
    if (n >= 2 && denominator > 0) fit.exponent = (nn * sxy - sx * sy) / denominator;
    return fit;
}

}  // namespace

const std::vector<std::string>& table_header() {
    static const std::vector<std::string> header{
        "scene",          "triangles", "method",     "tolerance",     "seconds",   "rays",
        "elements",       "links",     "peak MiB",   "rms error",     "max error", "error estimate",
        "estimate / rms", "status",    "stages (s)", "estimate parts"};
    return header;
}

std::vector<std::string> table_cells(const BenchRow& r) {
    return {r.scene,
            std::to_string(r.triangles),
            r.method,
            sci(r.tolerance),
            fixed(r.seconds, 3),
            std::to_string(r.rays),
            std::to_string(r.elements),
            std::to_string(r.links),
            fixed(r.peak_mib, 1),
            sci(r.rms_error),
            sci(r.max_error),
            sci(r.error_estimate),
            fixed(r.error_estimate / r.rms_error, 2),
            r.status,
            r.stages,
            r.estimate_parts};
}

void print_markdown_header(std::ostream& out) {
    const auto& header = table_header();
    out << '|';
    for (const auto& h : header) out << ' ' << h << " |";
    out << "\n|";
    for (std::size_t i = 0; i < header.size(); ++i) {
        const bool text = i == 0 || i == 2 || i + 3 >= header.size();
        out << (text ? " --- |" : " ---: |");
    }
    out << '\n';
}

void print_markdown_row(std::ostream& out, const BenchRow& row) {
    out << '|';
    for (const auto& c : table_cells(row)) out << ' ' << c << " |";
    out << '\n';
}

void print_csv_header(std::ostream& out) {
    const auto& header = table_header();
    for (std::size_t i = 0; i < header.size(); ++i) out << (i ? "," : "") << header[i];
    out << '\n';
}

void print_csv_row(std::ostream& out, const BenchRow& row) {
    const auto cells = table_cells(row);
    for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
    out << '\n';
}

bool plot_error_against_time(const std::vector<BenchRow>& rows, const std::filesystem::path& stem,
                             std::ostream& log) {
    // One curve per (scene, method), its points in order of time.
    std::map<std::pair<std::string, std::string>, std::vector<std::pair<double, double>>> curves;
    for (const auto& r : rows) {
        if (usable(r) && r.rms_error > 0) {
            curves[{r.scene, r.method}].push_back({r.seconds, r.rms_error});
        }
    }
    if (curves.empty()) {
        log << "radiant-bench: no rows with a positive error to plot\n";
        return false;
    }
    const std::filesystem::path script = stem.string() + ".gp";
    const std::filesystem::path png = stem.string() + ".png";
    {
        std::ofstream gp(script);
        gp << "set terminal pngcairo size 1280,900 noenhanced\n"
           << "set output '" << png.string() << "'\n"
           << "set logscale xy\nset format xy '%g'\nset grid\nset key outside right top\n"
           << "set xlabel 'seconds'\nset ylabel 'RMS relative error'\n"
           << "set title 'radiant-bench: error against time'\n";
        int block = 0;
        for (auto& [key, points] : curves) {
            std::sort(points.begin(), points.end());
            gp << "$d" << block++ << " << EOD\n";
            for (const auto& [t, e] : points) gp << t << ' ' << e << '\n';
            gp << "EOD\n";
        }
        gp << "plot ";
        block = 0;
        for (const auto& [key, points] : curves) {
            gp << (block ? ", \\\n     " : "") << "$d" << block << " with linespoints title '"
               << key.first << " " << key.second << "'";
            ++block;
        }
        gp << '\n';
    }
    const std::string command = "gnuplot '" + script.string() + "'";
    if (std::system(command.c_str()) != 0) {
        log << "radiant-bench: gnuplot failed or is missing (Debian: gnuplot-nox); the script is "
            << script.string() << '\n';
        return false;
    }
    log << "radiant-bench: wrote " << png.string() << '\n';
    return true;
}

void print_scaling(std::ostream& out, const std::vector<BenchRow>& rows,
                   const std::vector<std::string>& scenes) {
    std::map<std::pair<std::string, double>, std::vector<const BenchRow*>> series;
    for (const auto& r : rows) {
        // Only solves that finished: a capped run's time and memory say nothing about growth.
        if (r.status == "converged" &&
            std::find(scenes.begin(), scenes.end(), r.scene) != scenes.end()) {
            series[{r.method, r.tolerance}].push_back(&r);
        }
    }
    out << "\nScaling of converged solves (least-squares exponents against input triangles; last "
           "step: the two largest scenes):\n\n"
        << "| method | tolerance | scenes | time exponent | last step | memory exponent | last "
           "step | links per element |\n"
        << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
    for (auto& [key, members] : series) {
        std::sort(members.begin(), members.end(),
                  [](const BenchRow* a, const BenchRow* b) { return a->triangles < b->triangles; });
        std::vector<std::pair<double, double>> time, memory;
        std::string per_element;
        for (const BenchRow* r : members) {
            const double n = static_cast<double>(r->triangles);
            time.push_back({n, r->seconds});
            memory.push_back({n, r->peak_mib});
            per_element +=
                (per_element.empty() ? "" : " / ") +
                (r->elements
                     ? fixed(static_cast<double>(r->links) / static_cast<double>(r->elements), 1)
                     : std::string("n/a"));
        }
        const auto last_two = [](const std::vector<std::pair<double, double>>& v) {
            return log_log_slope({v.end() - std::min<std::size_t>(2, v.size()), v.end()});
        };
        out << "| " << key.first << " | " << sci(key.second) << " | " << members.size() << " | "
            << fixed(log_log_slope(time).exponent, 2) << " | " << fixed(last_two(time).exponent, 2)
            << " | " << fixed(log_log_slope(memory).exponent, 2) << " | "
            << fixed(last_two(memory).exponent, 2) << " | " << per_element << " |\n";
    }
}

void print_time_to_error(std::ostream& out, const std::vector<BenchRow>& rows, double target) {
    std::map<std::pair<std::string, std::string>, std::vector<const BenchRow*>> groups;
    for (const auto& r : rows) groups[{r.scene, r.method}].push_back(&r);
    out << "\nTime to an RMS error of at most " << sci(target) << ":\n\n"
        << "| scene | method | seconds | tolerance | rms error |\n| --- | --- | ---: | ---: | ---: "
           "|\n";
    for (const auto& [key, members] : groups) {
        const BenchRow* best = nullptr;
        const BenchRow* slowest = nullptr;
        for (const BenchRow* r : members) {
            if (!usable(*r)) continue;
            if (r->rms_error <= target && (!best || r->seconds < best->seconds)) best = r;
            if (!slowest || r->seconds > slowest->seconds) slowest = r;
        }
        out << "| " << key.first << " | " << key.second << " | ";
        if (best) {
            out << fixed(best->seconds, 3) << " | " << sci(best->tolerance) << " | "
                << sci(best->rms_error) << " |\n";
        } else if (slowest) {
            out << "not reached within " << fixed(slowest->seconds, 1) << " s | "
                << sci(slowest->tolerance) << " | " << sci(slowest->rms_error) << " |\n";
        } else {
            out << "no usable run | | |\n";
        }
    }
}

void print_estimate_misses(std::ostream& out, const std::vector<BenchRow>& rows) {
    // Issue 27: an estimate at or above the RMS error, and at most kTightFactor times it where
    // it is above kReadableError.
    constexpr double kReadableError = 1e-3;
    constexpr double kTightFactor = 4;
    struct Miss {
        const BenchRow* row;
        const char* kind;
    };
    std::size_t checked = 0, readable = 0, under = 0, loose = 0;
    std::vector<Miss> misses, unjudged;
    for (const auto& r : rows) {
        if (r.status != "converged" || !std::isfinite(r.rms_error)) continue;
        ++checked;
        // The true error is within the reference's own error of the measured one.
        const double doubt = std::isfinite(r.reference_error) ? r.reference_error : 0;
        if (r.rms_error > r.error_estimate) {
            ++under;
            (r.rms_error - doubt > r.error_estimate ? misses : unjudged).push_back({&r, "under"});
        }
        if (r.rms_error > kReadableError) {
            ++readable;
            if (r.error_estimate > kTightFactor * r.rms_error) {
                ++loose;
                const bool certain = r.error_estimate > kTightFactor * (r.rms_error + doubt);
                (certain ? misses : unjudged).push_back({&r, "loose"});
            }
        }
    }
    out << "\nError estimate against the RMS error: " << under << " of " << checked
        << " converged rows have a larger RMS error than their estimate; " << loose << " of the "
        << readable << " with an RMS error above " << sci(kReadableError)
        << " have an estimate more than " << sci(kTightFactor) << " times it; " << unjudged.size()
        << " of these misses are within the reference's own error estimate\n";
    auto list = [&](const std::vector<Miss>& which, const char* note) {
        for (const Miss& m : which) {
            const BenchRow& r = *m.row;
            out << "- " << m.kind << note << ": " << r.scene << " " << r.method << " "
                << sci(r.tolerance) << ": rms error " << sci(r.rms_error) << ", estimate "
                << sci(r.error_estimate) << ", reference's estimate " << sci(r.reference_error)
                << '\n';
        }
    };
    list(misses, "");
    list(unjudged, " (within the reference's error)");
}

}  // namespace radiant::bench
