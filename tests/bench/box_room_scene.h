// A box room (box_room_reference.h) as a radiant-scene/1 document, and its reference answer as
// expected-value checks in the format of tests/data/scenes/expected.json.
#pragma once

#include <nlohmann/json.hpp>

#include "box_room_reference.h"

namespace radiant::bench {

/// The six faces as polygons facing into the room, oriented like
/// tests/data/scenes/cube-ceiling-rho0.5.json; a face holding the panel becomes a mesh of the
/// eight rectangles around it, and the panel its own polygon named "panel".
nlohmann::ordered_json box_room_scene(const BoxRoom& room);

/// One check per surface and field (mean radiosity and mean irradiance) with `rel_tol`, plus
/// energy balance.
nlohmann::ordered_json box_room_checks(const BoxRoom& room, const BoxRoomReference& reference,
                                       double rel_tol);

}  // namespace radiant::bench
