// From each light component's values to what a lighting designer reads off a solve: maintained
// sensor values (initial ones beside them when a factor below 1 applies), UGR observers, the
// requirements checked, every group's contribution and the scene's light scenes.
#pragma once

#include <vector>

#include "radiant/result.h"
#include "scene/prepared_scene.h"

namespace radiant {

/// One light component's light, before maintenance, as a solve measured it.
struct ComponentValues {
    std::vector<std::vector<double>> sets;      ///< [sensor set][point], lux
    std::vector<double> set_error_lx;           ///< per sensor set: estimated RMS error, lux
    std::vector<double> eye_indirect_lx;        ///< per observer: E_ind at the eye, lux
    std::vector<double> eye_indirect_error_lx;  ///< per observer: its estimated error, lux
    std::vector<double> glare_sums;             ///< per observer: Σ L²ω/p² of its luminaires
};

/// Fills `result`'s sensors (replacing them), observers, maintenance, groups (kept when the
/// scene names groups or light scenes) and light scenes from `components` (one per
/// prepared.components.components). `scene` is the one solved (after expand_task_areas()).
void assemble_lighting(const Scene& scene, const PreparedScene& prepared,
                       const std::vector<ComponentValues>& components, Result& result);

}  // namespace radiant
