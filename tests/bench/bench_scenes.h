// The scenes radiant-bench generates, by name: the box offices office-x1 … office-x64
// (office_scene.h), and the cluttered furnished-office, furnished-office-ies and
// furnished-floor-x4 … -x64 (furnished_office_scene.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "radiant/scene.h"

namespace radiant::bench {

/// The box offices' scaling series, smallest first.
const std::vector<std::string>& office_series();

/// The single furnished rooms: furnished-office and furnished-office-ies.
const std::vector<std::string>& clutter_scenes();

/// The cluttered scaling series: furnished-office, then the floors of 4, 16 and 64 rooms.
const std::vector<std::string>& clutter_series();

/// Whether `name` is a scene generated_scene() makes.
bool is_generated_scene(const std::string& name);

/// The generated scene `name`, or nullopt with a message in `why` (an unknown name, an
/// unreadable downlight). furnished-office-ies reads its distribution from `downlight_ies`.
std::optional<Scene> generated_scene(const std::string& name,
                                     const std::filesystem::path& downlight_ies, std::string& why);

}  // namespace radiant::bench
