// Whole-file writes that never leave a half-written file behind.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace radiant::cli {

/// An output path that must not be written: it exists and is no regular file (a device such as
/// /dev/full, a directory, a pipe). Renaming over it would replace it; the CLI exits 2.
struct OutputRefused : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Throws OutputRefused when `path` exists and is not a regular file (or a link to one).
void check_output_path(const std::filesystem::path& path);

/// Writes `content` to a temporary file beside `path`, then renames it over `path` (atomic on
/// POSIX within one file system). Throws OutputRefused (see check_output_path), or
/// std::runtime_error on failure; `path` is then untouched.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace radiant::cli
