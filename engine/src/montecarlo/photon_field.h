// The reflected light as photons leave it: photons from the light sources bounce through the
// element mesh (Russian roulette on reflectance) and leave their flux on every side they land
// on. Tallies per side: all light (for the surfaces' averages) and what arrived after at least
// one reflection (the indirect field the sensors gather; direct light is found exactly there).
// The photons are traced in chunks keyed by their index, and chunks are added in index order,
// so the field is the same for any number of threads. Chunks fall into batches, whose spread
// measures the field's noise, at the sensors and of the surfaces' means (a scene without sensors
// states its error on those).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "montecarlo/element_mesh.h"
#include "montecarlo/light_sources.h"
#include "visibility/visibility.h"

namespace radiant {

class PhotonField {
public:
    static constexpr int kBatches = 16;
    static constexpr std::size_t kChunkPhotons = 128;

    PhotonField(const PreparedScene& scene, const ElementMesh& mesh, std::uint64_t seed);

    /// Traces at least `photons` more photons, in waves of whole rounds of kBatches chunks so
    /// that every batch holds as many. Returns the rays cast. `stop` is polled between waves.
    std::uint64_t trace(std::size_t photons, const LightSources& sources,
                        const Visibility& visibility, const std::function<bool()>& stop);

    std::size_t photons() const { return chunks_ * kChunkPhotons; }

    /// Irradiance (lux, per channel) on `side` after one reflection or more, per open area (what
    /// a gather ray that lands on the side sees), or per area where the side has no open area.
    Rgb indirect(int side) const;
    /// All irradiance on `side`, direct and reflected, averaged over the element's whole area:
    /// light that enters a gap narrower than the open-area test lands on the hidden part.
    Rgb total(int side) const;
    /// Photometric light reflected by `side` from indirect irradiance (ρ ⊙ H_ind), in batch `b`.
    double batch_reflected(int side, int batch) const {
        const auto s = static_cast<std::size_t>(side);
        return batch_[s * kBatches + static_cast<std::size_t>(batch)] * inverse_area_[s] *
               kBatches / static_cast<double>(photons());
    }
    /// The surfaces whose means count in the surfaces' error measure (counted_surfaces), by
    /// index into the scene's surfaces.
    const std::vector<int>& counted_surfaces() const { return counted_; }
    /// Photometric mean irradiance (lux) on the front of counted surface `k`, in batch `b`.
    double batch_surface_irradiance(std::size_t k, int b) const {
        return batch_surface_mean(k, b, 0);
    }
    /// Photometric mean light it reflects (ρ ⊙ H, lm/m²) in batch `b`.
    double batch_surface_reflected(std::size_t k, int b) const {
        return batch_surface_mean(k, b, 1);
    }
    /// The area-weighted mean over every surface's front of the photometric irradiance (lux),
    /// and of the light reflected (lm/m²).
    double mean_irradiance() const { return mean_front(0); }
    double mean_reflected() const { return mean_front(1); }
    std::size_t memory_bytes() const;
    /// What the surfaces' batch tallies cost per counted surface.
    static constexpr std::size_t kBytesPerCountedSurface = 2 * kBatches * sizeof(double);
    /// What the tallies cost per side.
    static constexpr std::size_t kBytesPerSide =
        2 * sizeof(Rgb) + kBatches * sizeof(float) + sizeof(double);
    /// What trace() holds while it runs: a wave of chunks' deposits, each photon leaving about
    /// 1 / (1 − ρ) of them where it survives a bounce with probability ρ on average (the
    /// area-weighted mean of the materials' highest channel); the lists may double as they grow.
    static std::size_t wave_bytes(double mean_reflectance);

private:
    /// A wave's deposits are summed by kSumParts + 1 threads at once: each side's tallies by
    /// the part its index falls in (side mod kSumParts), the surfaces' by one more, each in the
    /// chunks' order, so the sums do not depend on the threads. Summed by one thread, they held
    /// the cove lobby's photons 0.43 of its 1.7 s.
    static constexpr std::size_t kSumParts = 8;
    /// What a photon leaves on a side: its flux, and the photometric light the side reflects of
    /// it.
    struct SideDeposit {
        int side;
        bool indirect;
        Rgb flux;
        double reflected;
    };
    /// What it leaves on a surface's front: photometric irradiance and reflected light.
    struct FrontDeposit {
        int slot;  ///< the surface's index among the counted ones, or −1
        double irradiance, reflected;
    };
    /// A chunk's deposits: on sides, by the part that sums them, and on fronts, in the order made.
    struct ChunkDeposits {
        std::array<std::vector<SideDeposit>, kSumParts> sides;
        std::vector<FrontDeposit> fronts;
        void clear() {
            for (auto& part : sides) part.clear();
            fronts.clear();
        }
    };
    double batch_surface_mean(std::size_t k, int b, int what) const;
    double mean_front(int what) const;
    void trace_chunk(std::size_t chunk, const LightSources& sources, const Visibility& visibility,
                     ChunkDeposits& out, std::uint64_t& rays) const;
    /// Sums `wave` chunks' deposits, the first of them chunk `first`.
    void add_wave(const std::vector<ChunkDeposits>& deposits, std::size_t wave, std::size_t first);

    const PreparedScene& scene_;
    const ElementMesh& mesh_;
    std::uint64_t seed_;
    std::size_t chunks_ = 0;
    std::vector<Rgb> total_, indirect_;  ///< summed photon flux per side (divide by photons)
    std::vector<float> batch_;  ///< photometric ρ ⊙ indirect flux, [side · kBatches + b]
    std::vector<double> inverse_area_;  ///< per side, 1/m² (0 for a degenerate element)
    std::vector<int> counted_;          ///< surface indices
    std::vector<int> counted_slot_;     ///< per surface, its index in counted_ or −1
    /// photometric front flux, [(k · kBatches + b) · 2 + what], what 0: irradiance, 1: reflected
    std::vector<double> surface_batch_;
    std::array<double, 2> front_{0, 0};  ///< photometric front flux over every surface
    double total_area_m2_ = 0;           ///< of every surface
};

}  // namespace radiant
