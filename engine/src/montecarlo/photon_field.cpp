#include "montecarlo/photon_field.h"

#include <algorithm>

#include "geometry/cosine_direction.h"
#include "montecarlo/channel_product.h"
#include "parallel/fork_join.h"
#include "solution/result_difference.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

// Chunks traced between two looks at `stop` (32 Ki photons), a whole number of batch rounds;
// their deposits are held until the wave is summed (a few MB), enough chunks to keep every core
// busy.
constexpr std::size_t kWaveChunks = 32768 / PhotonField::kChunkPhotons;
static_assert(kWaveChunks % PhotonField::kBatches == 0);
// A photon in a furnace of reflectance 0.999 bounces a thousand times on average; this only
// stops one that a rounding error keeps inside a closed solid.
constexpr int kMaxBounces = 100000;
// Key of the photons' sample streams, apart from the sensors' and the mesh's.
constexpr std::uint64_t kPhotonStream = 0x70686f746f6eull;

}  // namespace

PhotonField::PhotonField(const PreparedScene& scene, const ElementMesh& mesh, std::uint64_t seed)
    : scene_(scene), mesh_(mesh), seed_(seed) {
    const std::size_t sides = mesh.sides().size();
    total_.assign(sides, Rgb{0, 0, 0});
    indirect_.assign(sides, Rgb{0, 0, 0});
    batch_.assign(sides * kBatches, 0.0f);
    inverse_area_.resize(sides);
    for (std::size_t s = 0; s < sides; ++s) {
        // A side with no open area is seen only through a gap narrower than the open-area test
        // (the faces between two books), lit by what enters it: its light over its whole area.
        const ElementSide& side = mesh.sides()[s];
        const double open = side.open_area_m2;
        const double area = open > 0 ? open : mesh[static_cast<std::size_t>(side.element)].area_m2;
        inverse_area_[s] = area > 0 ? 1 / area : 0.0;
    }
    const std::vector<bool> counted = radiant::counted_surfaces(scene.surface_area_m2);
    counted_slot_.assign(counted.size(), -1);
    for (std::size_t i = 0; i < counted.size(); ++i) {
        total_area_m2_ += scene.surface_area_m2[i];
        if (!counted[i]) continue;
        counted_slot_[i] = static_cast<int>(counted_.size());
        counted_.push_back(static_cast<int>(i));
    }
    surface_batch_.assign(counted_.size() * kBatches * 2, 0.0);
}

double PhotonField::batch_surface_mean(std::size_t k, int b, int what) const {
    const double area = scene_.surface_area_m2[static_cast<std::size_t>(counted_[k])];
    if (!chunks_ || !(area > 0)) return 0;
    const std::size_t at = (k * kBatches + static_cast<std::size_t>(b)) * 2;
    return surface_batch_[at + static_cast<std::size_t>(what)] * kBatches /
           (static_cast<double>(photons()) * area);
}

double PhotonField::mean_front(int what) const {
    if (!chunks_ || !(total_area_m2_ > 0)) return 0;
    return front_[static_cast<std::size_t>(what)] /
           (static_cast<double>(photons()) * total_area_m2_);
}

Rgb PhotonField::indirect(int side) const {
    const auto s = static_cast<std::size_t>(side);
    const double scale = chunks_ ? inverse_area_[s] / static_cast<double>(photons()) : 0.0;
    return {indirect_[s][0] * scale, indirect_[s][1] * scale, indirect_[s][2] * scale};
}

Rgb PhotonField::total(int side) const {
    const auto s = static_cast<std::size_t>(side);
    const double area = mesh_[static_cast<std::size_t>(mesh_.sides()[s].element)].area_m2;
    const double scale = chunks_ && area > 0 ? 1 / (area * static_cast<double>(photons())) : 0.0;
    return {total_[s][0] * scale, total_[s][1] * scale, total_[s][2] * scale};
}

std::size_t PhotonField::wave_bytes(double mean_reflectance) {
    const double deposits = 1 / (1 - std::clamp(mean_reflectance, 0.0, 0.98));
    return static_cast<std::size_t>(
        2 * deposits *
        static_cast<double>(kWaveChunks * kChunkPhotons *
                            (sizeof(SideDeposit) + sizeof(FrontDeposit))));
}

std::size_t PhotonField::memory_bytes() const {
    return (total_.capacity() + indirect_.capacity()) * sizeof(Rgb) +
           batch_.capacity() * sizeof(float) +
           (inverse_area_.capacity() + surface_batch_.capacity()) * sizeof(double) +
           (counted_.capacity() + counted_slot_.capacity()) * sizeof(int);
}

void PhotonField::trace_chunk(std::size_t chunk, const LightSources& sources,
                              const Visibility& visibility, ChunkDeposits& out,
                              std::uint64_t& rays) const {
    const double eps = visibility.epsilon();
    const double t_max = 4 * scene_.diagonal_m + 1;
    for (std::size_t p = 0; p < kChunkPhotons; ++p) {
        SampleStream rng(seed_, kPhotonStream, chunk * kChunkPhotons + p);
        Photon photon = sources.emit(rng);
        Vec3 origin = photon.origin, direction = photon.direction;
        Rgb flux = photon.flux;
        for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
            ++rays;
            const RayHit hit = visibility.intersect(origin, direction, t_max);
            if (hit.triangle < 0) break;
            const int side = mesh_.side_hit(hit.triangle, direction);
            if (side < 0) break;
            const MeshElement& e = mesh_[static_cast<std::size_t>(hit.triangle)];
            const Rgb& rho = scene_.materials[static_cast<std::size_t>(e.material)].reflectance;
            const double reflected = photometric(times(rho, flux), scene_.channels);
            out.sides[static_cast<std::size_t>(side) % kSumParts].push_back(
                {side, bounce > 0, flux, reflected});
            if (side == e.front) {
                out.fronts.push_back({counted_slot_[static_cast<std::size_t>(e.surface)],
                                      photometric(flux, scene_.channels), reflected});
            }
            const double survive = std::min(1.0, std::max({rho[0], rho[1], rho[2]}));
            if (!(survive > 0) || rng.next() >= survive) break;
            for (int c = 0; c < 3; ++c) flux[c] *= rho[c] / survive;
            const Vec3 n = mesh_.side_normal(side);
            origin = origin + direction * hit.t + n * eps;
            direction = cosine_direction(n, rng.next(), rng.next());
        }
    }
}

void PhotonField::add_wave(const std::vector<ChunkDeposits>& deposits, std::size_t wave,
                           std::size_t first) {
    parallel_for(0, kSumParts + 1, [&](std::size_t part) {
        for (std::size_t k = 0; k < wave; ++k) {
            const std::size_t batch = (first + k) % kBatches;
            if (part == kSumParts) {
                for (const FrontDeposit& d : deposits[k].fronts) {
                    front_[0] += d.irradiance;
                    front_[1] += d.reflected;
                    if (d.slot < 0) continue;
                    const std::size_t at =
                        (static_cast<std::size_t>(d.slot) * kBatches + batch) * 2;
                    surface_batch_[at] += d.irradiance;
                    surface_batch_[at + 1] += d.reflected;
                }
                continue;
            }
            for (const SideDeposit& d : deposits[k].sides[part]) {
                const auto s = static_cast<std::size_t>(d.side);
                for (int c = 0; c < 3; ++c) total_[s][c] += d.flux[c];
                if (!d.indirect) continue;
                for (int c = 0; c < 3; ++c) indirect_[s][c] += d.flux[c];
                batch_[s * kBatches + batch] += static_cast<float>(d.reflected);
            }
        }
    });
}

std::uint64_t PhotonField::trace(std::size_t photons, const LightSources& sources,
                                 const Visibility& visibility, const std::function<bool()>& stop) {
    if (sources.empty()) return 0;
    const std::size_t round = kBatches * kChunkPhotons;
    std::size_t remaining = (photons + round - 1) / round * kBatches;
    std::uint64_t rays = 0;
    std::vector<ChunkDeposits> deposits(kWaveChunks);
    std::vector<std::uint64_t> wave_rays(kWaveChunks);
    while (remaining > 0 && !stop()) {
        const std::size_t wave = std::min(remaining, kWaveChunks);
        parallel_for(0, wave, [&](std::size_t k) {
            deposits[k].clear();
            wave_rays[k] = 0;
            trace_chunk(chunks_ + k, sources, visibility, deposits[k], wave_rays[k]);
        });
        add_wave(deposits, wave, chunks_);
        for (std::size_t k = 0; k < wave; ++k) rays += wave_rays[k];
        chunks_ += wave;
        remaining -= wave;
    }
    return rays;
}

}  // namespace radiant
