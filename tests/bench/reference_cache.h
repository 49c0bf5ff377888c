// Converged reference solves are slow, so the benchmark keeps them on disk (by default in the
// build directory). An entry is used only when it was made from the same scene (fingerprint),
// at the same tolerance, and after the engine library was last built.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "radiant/scene.h"

namespace radiant::bench {

/// FNV-1a over everything that can change a solve: geometry, materials, sources, sensors.
std::uint64_t scene_fingerprint(const Scene& scene);

struct CachedReference {
    std::vector<double> illuminance;  ///< of the scene's first sensor set, new lamps
    double seconds = 0;
    double error_estimate = 0;
};

class ReferenceCache {
public:
    explicit ReferenceCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

    std::optional<CachedReference> find(const Scene& scene, double tolerance) const;
    void store(const Scene& scene, double tolerance, const CachedReference& reference) const;

private:
    std::filesystem::path file_for(const Scene& scene, double tolerance) const;
    std::filesystem::path directory_;
};

}  // namespace radiant::bench
