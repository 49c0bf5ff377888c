// A scene without light (every Honeybee import, until luminaires are added) solves to 0 lx
// everywhere; an emitting material no surface uses lights nothing; a lamp's watts typed as its
// flux light a room a hundredth as much as meant.
#pragma once

#include <vector>

#include "checks/modelling_checks.h"

namespace radiant {

/// no_light when nothing emits; emission_unused for each emitting material on no surface;
/// flux_suspect when the light given as flux is far too little for any furnished room.
void check_emission(const Scene& scene, const PreparedScene& prepared, std::vector<Warning>& out);

}  // namespace radiant
