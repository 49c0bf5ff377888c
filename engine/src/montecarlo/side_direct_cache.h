// The direct light each element side reflects (photometric ρ ⊙ E_direct, lux), read once at its
// element's centroid by one next-event estimate and kept: the control variate of the sensors'
// final gather (SensorGather). In a room lit mostly from its surfaces (coves, uplights) what
// spreads a gather's ray sets is which elements its rays land on, not how the light varies
// across them; many cheap rays reading these values take that spread, and the few exact rays
// only the difference. Sides are read as rays land on them, by whichever thread lands first:
// each side draws from its own stream, so its value and the rays it took are the same whichever
// thread reads it, and both are counted once.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

#include "montecarlo/element_mesh.h"
#include "montecarlo/light_sources.h"

namespace radiant {

class SideDirectCache {
public:
    static constexpr std::size_t kBytesPerSide = sizeof(std::atomic<float>);

    SideDirectCache(const PreparedScene& scene, const ElementMesh& mesh,
                    const LightSources& sources, const Visibility& visibility, std::uint64_t seed);

    /// The direct light side `side` reflects (lux), read on first use. Thread-safe.
    double reflected(int side) const;
    /// The rays its reads have cast so far.
    std::uint64_t rays() const { return rays_.load(std::memory_order_relaxed); }
    std::size_t memory_bytes() const { return size_ * kBytesPerSide; }

private:
    const PreparedScene& scene_;
    const ElementMesh& mesh_;
    const LightSources& sources_;
    const Visibility& visibility_;
    std::uint64_t seed_;
    std::size_t size_;
    std::unique_ptr<std::atomic<float>[]> values_;  ///< kUnread until read
    mutable std::atomic<std::uint64_t> rays_{0};
};

}  // namespace radiant
