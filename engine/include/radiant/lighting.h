// What a lighting designer signs off, computed from a solved result without solving again: the
// EN 12464-1 activity table, and light scenes as weighted sums of the groups' contributions.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant {

/// One row of the built-in EN 12464-1:2011 table (Table 5.26, offices).
struct Activity {
    std::string_view reference;  ///< the standard's reference number, e.g. "5.26.2"
    std::string_view name;
    double em_lx = 0;  ///< maintained illuminance Ēm on the task area, lux
    double u0 = 0;     ///< uniformity U₀
    double ugr_l = 0;  ///< unified glare rating limit UGR_L
    double ra = 0;     ///< colour rendering index
};

/// The activities a requirement may name by reference number.
std::span<const Activity> en12464_activities();

/// A light scene from `solved`'s group contributions (Result::groups): every sensor set and
/// observer as a solve of the scene with each group dimmed would give them, within the groups'
/// error estimates, with requirements checked again. Light is linear in the emission, so each
/// value is Σ dimming × contribution (UGR: its background luminance is that sum, its glare sum
/// Σ dimming² × the group's). Cost linear in sensor points and groups. Problems — a group the
/// solve does not have, a dimming outside [0, 1], a result without groups — carry pointers
/// into the light scene ("/dimming/GROUP"). Thread-safe; pure.
std::variant<LightSceneResult, std::vector<Problem>> evaluate_light_scene(const Result& solved,
                                                                          const LightScene& scene);

}  // namespace radiant
