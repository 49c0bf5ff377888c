// Running RADIANCE's oconv and rtrace on a converted scene: where they are, the RAYPATH they
// need, and the wall time of a run. RADIANCE is never built or shipped by this project
// (docs/radiance-peer.md says how to build it outside).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "radiance_export.h"

namespace radiant::radiance {

/// The directory on PATH that holds both `oconv` and `rtrace`, if any.
std::optional<std::filesystem::path> find_radiance();

/// RAYPATH for RADIANCE in `bin`: the environment's (else "."), then `bin`/../lib when it holds
/// rayinit.cal (a CMake build directory, or an install made with CMAKE_INSTALL_PREFIX).
std::string raypath_for(const std::filesystem::path& bin);

struct RtraceRun {
    bool ok = false;
    std::string error;
    double seconds = 0;  ///< wall time of rtrace alone (oconv is not counted)
    std::vector<Rgb> irradiance_lux;
};

/// Runs `oconv scene.rad > scene.oct` in `dir` (written by write_radiance_scene) unless
/// scene.oct exists. Returns an empty string or why it failed.
std::string make_octree(const std::filesystem::path& bin, const std::filesystem::path& dir);

/// `rtrace -I -h SETTINGS scene.oct < POINTS` in `dir`; `settings` are rtrace options (e.g.
/// "-ab 8 -aa 0 -ad 2048 -n 2"). Checks that there is one result per line of `points`.
RtraceRun run_rtrace(const std::filesystem::path& bin, const std::filesystem::path& dir,
                     const std::string& settings, const std::string& points = "points.txt");

}  // namespace radiant::radiance
