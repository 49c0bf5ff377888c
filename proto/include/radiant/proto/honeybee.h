// Honeybee models (HBJSON, ladybug-tools' honeybee-schema) → radiant-scene/1 documents.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/scene.h"

namespace radiant::proto {

struct HoneybeeOutcome {
    std::optional<nlohmann::ordered_json> scene;  ///< set only when `problems` is empty
    std::vector<Problem> problems;                ///< pointers into the HBJSON document
};

/// Converts a Honeybee Model: rooms' faces (AirBoundary faces are left out, so light passes),
/// their apertures and doors (coplanar polygons over the face, which hide it there), indoor and
/// orphaned shades (two-sided), and radiance sensor grids (one sensor set per grid and sensor
/// direction). Faces turn to face into their room. Reflectances come from the face's radiance
/// modifier when it is a plastic or metal one, else from defaults by face type. Units carry
/// over. The result has no luminaires: add them before solving. Never throws for bad input.
HoneybeeOutcome honeybee_to_scene(std::string_view hbjson_text);

}  // namespace radiant::proto
