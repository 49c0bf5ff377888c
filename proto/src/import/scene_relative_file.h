// Files a scene names by a `*_file` key (models, photometric files): read relative to the scene
// file's directory, with a size limit, never on a service client's behalf.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace radiant::proto {

/// Reads `name` relative to `scene_directory` into `bytes`; returns the problem, if any (also
/// when there is no scene directory: the scene was not read from a file).
std::optional<std::string> read_scene_relative_file(
    const std::optional<std::filesystem::path>& scene_directory, const std::string& name,
    std::size_t max_bytes, std::string& bytes);

}  // namespace radiant::proto
