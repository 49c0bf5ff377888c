// A scene without light (every Honeybee import, until luminaires are added) solves to 0 lx
// everywhere; an emitting material no surface uses lights nothing.
#pragma once

#include <vector>

#include "checks/modelling_checks.h"

namespace radiant {

/// no_light when nothing emits; emission_unused for each emitting material on no surface.
void check_emission(const Scene& scene, const PreparedScene& prepared, std::vector<Warning>& out);

}  // namespace radiant
