// The lighting-design parts of radiant-result/1 ⇄ engine types: requirement checks, UGR
// observers, group contributions and light scenes; and the light scene a client posts.
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/result.h"

namespace radiant::proto {

/// A sensor set's lighting-design members (kind, error_estimate, and when set initial,
/// surrounding_of, compliance), added to `set`.
void add_sensor_design(const SensorResult& sensors, nlohmann::json& set);

/// The result members `maintenance`, `observers`, and when the solve kept them `groups` and
/// `light_scenes`, added to `doc`.
void add_lighting(const Result& result, nlohmann::json& doc);

/// One light scene of the result (its `sensors` written by `sensors_json`).
nlohmann::json light_scene_to_json(const LightSceneResult& scene);

/// A posted light scene: {"name": "...", "dimming": {"GROUP": 0–1, ...}}; problems carry
/// pointers into the body. Never throws.
std::variant<LightScene, std::vector<Problem>> parse_light_scene(std::string_view body);

}  // namespace radiant::proto
