// Light scenes as sums: every value of a scene with its groups dimmed is Σ dimming × the group's
// contribution (light is linear in the emission); a UGR's background luminance is that sum and
// its glare sum Σ dimming² × the group's (luminance squared).
#pragma once

#include <vector>

#include "radiant/result.h"

namespace radiant {

/// The sensor sets and observers of `groups` dimmed by `dimming` (one per group): sets shaped
/// like `sensors` (name, grid, kind, band, and the requirement in `compliance`, checked again),
/// observers like `observers`. Each set's error estimate is Σ dimming × the groups' RMS errors
/// over its mean: a bound for any correlation between the groups' errors (Minkowski).
LightSceneResult sum_groups(const std::vector<SensorResult>& sensors,
                            const std::vector<ObserverResult>& observers,
                            const std::vector<GroupContribution>& groups,
                            const std::vector<double>& dimming);

}  // namespace radiant
