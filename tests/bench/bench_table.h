// The benchmark's rows and every way it reports them: a Markdown table on stdout and in a file,
// CSV, a gnuplot script and PNG of error against time, the scaling exponents, and the time
// each method needs to reach a target error.
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace radiant::bench {

struct BenchRow {
    std::string scene;
    std::size_t triangles = 0;  ///< input triangles (mesh faces and polygons as fans)
    std::string method;
    double tolerance = 0;
    double seconds = 0;
    std::uint64_t rays = 0;
    std::size_t elements = 0, links = 0;
    double peak_mib = 0;
    double rms_error = 0, max_error = 0;  ///< relative, against the scene's reference
    double error_estimate = 0;
    double reference_error = 0;  ///< the reference's own error estimate (see ReferenceAnswer)
    std::string status;          ///< converged, stopped, failed, crashed; a peer's runs: done
    std::string setting;         ///< a peer's command-line settings (empty for Radiant's rows)
    std::string stages;          ///< seconds per stage of the solve
    std::string estimate_parts;  ///< the estimate's non-zero parts (stats.error_parts)
};

/// A table cell: `v` with `digits` decimals, or "n/a" for NaN.
std::string fixed(double v, int digits);
/// A table cell: `v` to three significant digits, or "n/a" for NaN.
std::string sci(double v);

const std::vector<std::string>& table_header();
std::vector<std::string> table_cells(const BenchRow& row);

void print_markdown_header(std::ostream& out);
void print_markdown_row(std::ostream& out, const BenchRow& row);
void print_csv_header(std::ostream& out);
void print_csv_row(std::ostream& out, const BenchRow& row);

/// Writes `<stem>.gp` (a self-contained gnuplot script with the data inline) and runs gnuplot on
/// it to make `<stem>.png`: RMS error against seconds, log-log, one line per method and scene.
/// Returns false (with a message on `log`) when gnuplot is missing or fails.
bool plot_error_against_time(const std::vector<BenchRow>& rows, const std::filesystem::path& stem,
                             std::ostream& log);

/// For each method and tolerance over the converged rows of `scenes` (a scaling series): the
/// least-squares exponents of seconds and of peak memory against input triangles, and links
/// per element.
void print_scaling(std::ostream& out, const std::vector<BenchRow>& rows,
                   const std::vector<std::string>& scenes);

/// For each scene and method, the least time among rows whose RMS error is at most `target`.
void print_time_to_error(std::ostream& out, const std::vector<BenchRow>& rows, double target);

/// Issue 27's rule for the estimate, row by row: the rows whose RMS error against the reference
/// exceeds their estimate, and those whose RMS error is above 0.1 % and under a quarter of it.
/// The true error lies within the reference's own error of the measured one, so a row that
/// misses only by less than that is listed apart, as one the reference cannot judge.
void print_estimate_misses(std::ostream& out, const std::vector<BenchRow>& rows);

}  // namespace radiant::bench
