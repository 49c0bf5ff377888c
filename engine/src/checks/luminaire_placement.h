// Luminaires whose light cannot reach the room as meant: inside a closed solid, behind the black
// back of a surface (5 cm above the ceiling), on a surface or aimed into the one they hang
// under, or outside the model altogether.
#pragma once

#include <vector>

#include "checks/light_paths.h"

namespace radiant {

/// One warning per misplaced luminaire, the most telling of luminaire_inside_solid,
/// luminaire_behind_surface, luminaire_faces_surface and luminaire_outside_model. Returns which
/// luminaires it warned about.
std::vector<bool> check_luminaire_placement(const CheckedScene& input, const LightPaths& paths,
                                            std::vector<Warning>& out);

}  // namespace radiant
