// RADIANCE as the benchmark's peer (docs/radiance-peer.md): each scene converted with
// radiant-to-radiance's library and traced with rtrace -I over a ladder of settings, each run
// timed (wall) and scored against the same reference as Radiant's rows; the time each tool needs
// to reach an error; and a RADIANCE reference made of many independent runs.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bench_table.h"
#include "radiant/scene.h"
#include "reference_answer.h"

namespace radiant::bench {

/// rtrace options of one rung (without -I, -h and -n, which the peer adds).
using RadianceSetting = std::string;

/// From coarse to fine: -ab 2 … 8 and a last rung at 16, -ad 128 … 4096, -lw 1e-3 … 1e-5,
/// -aa 0 (no irradiance cache: every point is an independent Monte Carlo estimate, as the
/// reference's are), direct light from -ds 0.2 -dt 0.05 down to -ds 0.05 -dt 0 -dc 1.
const std::vector<RadianceSetting>& default_radiance_ladder();

struct PeerOptions {
    int threads = 1;                 ///< rtrace -n: the core count Radiant's rows use
    std::filesystem::path work_dir;  ///< one subdirectory per scene, kept for inspection
    std::vector<RadianceSetting> ladder = default_radiance_ladder();
    int surface_samples = 256;  ///< per surface a check names (surface averages)
};

/// The directory with oconv and rtrace, or nothing (with a note on `log`: the peer is skipped).
std::optional<std::filesystem::path> radiance_for_peer(std::ostream& log);

/// One row per rung that ran: method "radiance", `setting` the rung, `seconds` rtrace's wall
/// time, errors as relative_error() computes Radiant's (an `energy` check cannot be measured by
/// rtrace -I and is left out), status "done" (or "failed", with the reason on `log`).
std::vector<BenchRow> run_radiance_peer(const std::filesystem::path& radiance, const Scene& scene,
                                        const ReferenceAnswer& reference,
                                        const std::string& row_name, std::size_t triangles,
                                        const PeerOptions& options, std::ostream& log);

/// Markdown table of the peer's rows: scene, setting, seconds, RMS and largest error.
void print_peer_table(std::ostream& out, const std::vector<BenchRow>& rows);

/// Time a curve needs to reach `target` RMS error: on the lower envelope of its (seconds, error)
/// points, log-log interpolated between the last point above and the first at or below it.
/// `at_most` is set when even the fastest point is below the target (its time is an upper
/// bound). Empty when no point reaches the target.
struct TimeToError {
    double seconds = 0;
    bool at_most = false;
};
std::optional<TimeToError> interpolated_time_to_error(const std::vector<BenchRow>& curve,
                                                      double target);

/// For each scene with peer rows and each Radiant method: the time each needs for every target
/// error, and RADIANCE's time over Radiant's (> 1: Radiant is faster).
void print_equal_error_speed(std::ostream& out, const std::vector<BenchRow>& rows,
                             const std::vector<double>& targets);

struct RadianceReferenceOptions {
    int runs = 4;  ///< independent runs (rtrace -u+, each started in its own second)
    /// -dj 1: without jitter, reflected rays' shadow rays aim at an area source's centre
    /// (rtrace cuts sources into parts only for rays of high weight), see docs/radiance-peer.md.
    RadianceSetting setting = "-ab 1000 -lr 0 -lw 5e-6 -aa 0 -ad 16384 -ds 0.01 -dt 0 -dc 1 -dj 1";
    int threads = 1;
    /// The median of the runs at each point instead of their mean: a rare bright path that one
    /// run samples (the warehouse's floor beside a high-bay: 699 lx once in eight runs, 613–615
    /// lx the others) moves a mean of a few runs by per cents, and the median not.
    bool median = false;
    std::filesystem::path work_dir;
};

/// Averages `runs` independent RADIANCE runs at the first sensor set's points (or takes their
/// median) and writes them as `x,y,z,irradiance` (lux; the format of
/// tests/data/radiance/room-s2.reference.csv), with a fifth column `standard_error` (lux; of a
/// median, √(π/2) times the mean's) when there are several runs. Prints each run's time and the
/// noise: the standard error's RMS and largest value relative to the mean illuminance. Returns
/// false (with the reason on `log`) on failure.
bool write_radiance_reference(const std::filesystem::path& radiance, const Scene& scene,
                              const std::filesystem::path& csv,
                              const RadianceReferenceOptions& options, std::ostream& out,
                              std::ostream& log);

}  // namespace radiant::bench
