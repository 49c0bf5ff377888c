// Where the emitted light goes, roughly: a few thousand light paths from the luminaires and the
// emitting surfaces, bounced diffusely (Russian roulette on the reflectance) until they are
// absorbed, lost into a black back, or leave the model. Cheap next to any solve, and the same
// whatever method solves the scene.
#pragma once

#include <cstdint>
#include <vector>

#include "checks/modelling_checks.h"

namespace radiant {

/// What one luminaire's light meets first, as shares of its flux.
struct LuminaireFirstHits {
    double escaped = 0;     ///< leaves the model without meeting a surface
    double black_back = 0;  ///< falls on the black back of a one-sided surface
    int main_surface = -1;  ///< the surface whose black back takes most of it (−1: none)
    double main_share = 0;  ///< that surface's share
    /// Shares of the directions around it, whether it sends light there or not, that end on
    /// black backs and that leave the model: what surrounds the luminaire.
    double directions_black = 0;
    double directions_escaped = 0;
    /// Sent straight into the front of a surface it lies on (within kTouchDistance: placed on the
    /// ceiling itself), and the surface that takes most of it (−1: none).
    double touching = 0;
    int touching_surface = -1;
    /// Meets a surface first within near_distance(), and the surface that takes most of it; and
    /// the same share of what it would send aimed the other way (its intensities mirrored
    /// through its position): a downlight aimed up under the ceiling sends all of its light
    /// there, and none the other way.
    double near = 0;
    double near_reversed = 0;
    int near_surface = -1;
};

/// A luminaire this near a surface lies on it (metres): its light into the surface is lost.
inline constexpr double kTouchDistance = 1e-3;
/// What LuminaireFirstHits::near counts as near: 10 cm, or 5 % of a smaller model's diagonal.
double near_distance(const PreparedScene& prepared);

/// A path that ended on a black back: where, and what it carried.
struct LostPath {
    int surface = 0;
    int luminaire = -1;  ///< the luminaire it left; −1: an emitting surface
    int emitter = -1;    ///< the emitting surface (engine index) it left; −1: a luminaire
    double flux_lm = 0;
};

struct LightPaths {
    double emitted_lm = 0;       ///< photometric; 0 when nothing emits
    double escaped_lm = 0;       ///< left the model, after any number of bounces
    std::vector<LostPath> lost;  ///< in path order
    std::vector<LuminaireFirstHits> luminaires;
};

/// Per engine surface, the share of the emitted light lost into its black back, leaving out
/// the light of the luminaires marked in `excluded` and of the emitting surfaces (engine
/// index) marked in `excluded_emitters` (misplaced ones, already warned about).
std::vector<double> black_back_shares(const LightPaths& paths, std::size_t surfaces,
                                      const std::vector<bool>& excluded,
                                      const std::vector<bool>& excluded_emitters);

/// Traces the paths (at least kLightPaths of them, more with many luminaires). Counts the rays
/// cast into `rays`.
LightPaths trace_light_paths(const CheckedScene& input, std::uint64_t& rays);

/// Light paths traced for a scene: enough for a share of a few percent to be known to a few
/// tenths of a percent.
inline constexpr std::size_t kLightPaths = 8192;

}  // namespace radiant
