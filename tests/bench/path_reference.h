// A reference for a scene's first sensor set that shares none of the Monte Carlo solver's
// approximations: brute-force path tracing from each point, with the direct light at every
// landing from next-event estimation and no mesh, photon field or element average. It shares
// with Radiant only the prepared geometry, the ray tracer and the direct light (LightSources),
// which RADIANCE checks; where RADIANCE itself reads dark (light leaving a cove's trough or a
// lamp's shade after several bounces, docs/radiance-peer.md) it is the benchmark's reference.
// About 15 times slower than the final gather for the same noise.
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>

#include "radiant/scene.h"

namespace radiant::bench {

struct PathReferenceOptions {
    /// Paths per point double until the points' RMS standard error is at most this share of
    /// their mean illuminance, or until `max_paths`.
    double relative_error = 0.002;
    long max_paths = 1L << 24;
    int threads = 0;  ///< 0: one per core
    std::uint64_t seed = 1;
};

/// Traces the first sensor set of `scene` (planar or vertical) and writes it to `csv` as
/// `x,y,z,irradiance,standard_error` (metres, lux). Progress and the summary go to `out`,
/// problems to `log`; false when the scene has no such sensor set or the file cannot be written.
bool write_path_reference(const Scene& scene, const std::filesystem::path& csv,
                          const PathReferenceOptions& options, std::ostream& out,
                          std::ostream& log);

}  // namespace radiant::bench
