#include "montecarlo/side_direct_cache.h"

#include "montecarlo/channel_product.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

constexpr float kUnread = -1;  // no side reflects negative light
constexpr std::uint64_t kCacheStream = 0x73696465ull;

}  // namespace

SideDirectCache::SideDirectCache(const PreparedScene& scene, const ElementMesh& mesh,
                                 const LightSources& sources, const Visibility& visibility,
                                 std::uint64_t seed)
    : scene_(scene),
      mesh_(mesh),
      sources_(sources),
      visibility_(visibility),
      seed_(seed),
      size_(mesh.sides().size()),
      values_(std::make_unique<std::atomic<float>[]>(size_)) {
    for (std::size_t s = 0; s < size_; ++s) values_[s].store(kUnread, std::memory_order_relaxed);
}

double SideDirectCache::reflected(int side) const {
    std::atomic<float>& slot = values_[static_cast<std::size_t>(side)];
    float value = slot.load(std::memory_order_relaxed);
    if (value != kUnread) return value;
    const ElementSide& s = mesh_.sides()[static_cast<std::size_t>(side)];
    const MeshElement& e = mesh_[static_cast<std::size_t>(s.element)];
    const Vec3 centroid = (e.triangle.a + e.triangle.b + e.triangle.c) / 3.0;
    SampleStream rng(seed_, kCacheStream, static_cast<std::uint64_t>(side));
    std::uint64_t rays = 0;
    const Rgb h = sources_.direct_at(centroid, mesh_.side_normal(side), visibility_, rng, rays);
    const Rgb& rho = scene_.materials[static_cast<std::size_t>(e.material)].reflectance;
    value = static_cast<float>(photometric(times(rho, h), scene_.channels));
    float expected = kUnread;
    // A thread that lost the race read the same value with the same rays: count them once.
    if (slot.compare_exchange_strong(expected, value, std::memory_order_relaxed))
        rays_.fetch_add(rays, std::memory_order_relaxed);
    return value;
}

}  // namespace radiant
