// The web viewer's files (clients/web, built into share/radiant/web): GET and HEAD of any path
// outside the API answer with a file under one root directory, or 404. Nothing outside the root
// is ever read: paths with `..`, `.`-names (dotfiles), backslashes or NUL are refused before the
// file system is asked, and a symbolic link that leads out of the root is refused too.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "radiant/server/http.h"

namespace radiant::server {

/// The file under `root` that the URL path `url_path` (still percent-encoded) names, without
/// touching the disk: `/` and paths ending in `/` name their `index.html`. Nothing for a path
/// that may not be served.
std::optional<std::filesystem::path> static_file_path(const std::filesystem::path& root,
                                                      std::string_view url_path);

/// The Content-Type for a file name's extension (text types in UTF-8); unknown ones are
/// application/octet-stream, so a browser never guesses (the answers carry `nosniff`).
const char* static_content_type(const std::filesystem::path& file);

class StaticFiles {
public:
    /// Serves nothing: every path answers 404 (radiantd without its viewer).
    StaticFiles() = default;
    explicit StaticFiles(std::filesystem::path root);

    /// True when the root holds an index.html, i.e. the viewer is installed there.
    bool installed() const;
    const std::filesystem::path& root() const { return root_; }

    /// The answer to GET or HEAD of `url_path`: the file with its type, or a JSON 404.
    Response serve(const Request& request, std::string_view url_path) const;

private:
    std::filesystem::path root_;
};

}  // namespace radiant::server
