// Warnings: a scene that solves, but most likely not as its author meant (a luminaire above the
// ceiling, a ceiling wound the wrong way, a room in the wrong units). docs/warnings.md lists the
// codes and what to do about each.
#pragma once

#include <string>
#include <vector>

#include "radiant/scene.h"

namespace radiant {

struct Warning {
    std::string code;     ///< stable, snake_case, e.g. "luminaire_behind_surface"
    std::string message;  ///< names the surface, luminaire or sensor set it is about
    std::string pointer;  ///< JSON pointer into the scene document ("" = the whole scene)
};

/// The modelling checks that need no solve: names, units, emission, where luminaires and
/// sensors are, boxes that face the wrong way, and light lost into the black backs of one-sided
/// surfaces (traced with a few thousand rays). Prepares the scene and builds a ray tracer of
/// its own; solve() runs the same checks on the one it builds anyway. `scene` must have passed
/// check_scene(). Deterministic. Thread-safe for distinct calls.
std::vector<Warning> check_modelling(const Scene& scene);

/// "code: pointer: message" of each, joined by "; ": the error text of a strict refusal.
std::string describe_warnings(const std::vector<Warning>& warnings);

}  // namespace radiant
