#include "montecarlo/control_pilot.h"

#include <array>

namespace radiant {
namespace {

constexpr std::array<int, 5> kCheapChoices = {64, 128, 256, 512, 1024};
// A cheap ray costs its one ray and, the first time its side is landed on, that side's read:
// counted as this many rays.
constexpr double kCheapRayCost = 1.25;
// Cheap rays keep a side per ray: below this gain their memory is not worth it.
constexpr double kLeastGain = 1.2;

}  // namespace

int cheap_rays_per_set(const ControlPilot& pilot, int exact_rays) {
    const double cost = pilot.sets > 0 ? pilot.rays / pilot.sets : 0.0;
    if (!(pilot.plain > 0) || !(cost > 0)) return 0;
    int best = 0;
    double best_gain = kLeastGain;
    for (const int m : kCheapChoices) {
        const double variance = pilot.residual + pilot.control * exact_rays / m;
        const double gain = pilot.plain * cost / (variance * (cost + kCheapRayCost * m));
        if (gain > best_gain) {
            best = m;
            best_gain = gain;
        }
    }
    return best;
}

}  // namespace radiant
