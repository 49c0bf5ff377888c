// Test helpers: load a scene file through the proto layer (as the CLI does) and solve it.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"

namespace radiant::testing {

inline std::filesystem::path data_path(const std::string& relative) {
    return std::filesystem::path(RADIANT_TEST_DATA) / relative;
}

/// Parses a scene; fails the test with the problems when it does not validate.
inline Scene load_scene(const std::filesystem::path& path) {
    auto outcome = proto::load_scene_file(path);
    for (const auto& p : outcome.problems) ADD_FAILURE() << proto::format_problem(path.string(), p);
    return outcome.scene.value_or(Scene{});
}

inline const SurfaceResult* find_surface(const Result& r, const std::string& name) {
    for (const auto& s : r.surfaces) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

inline const SensorResult* find_sensor(const Result& r, const std::string& name) {
    for (const auto& s : r.sensors) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

}  // namespace radiant::testing
