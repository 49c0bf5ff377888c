// Whole-file writes that never leave a half-written file behind.
#pragma once

#include <filesystem>
#include <string_view>

namespace radiant::cli {

/// Writes `content` to a temporary file beside `path`, then renames it over `path` (atomic on
/// POSIX within one file system). Throws std::runtime_error on failure; `path` is then untouched.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace radiant::cli
