#include "radiant/server/static_files.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>

namespace radiant::server {
namespace {

namespace fs = std::filesystem;

/// The viewer loads only its own files and talks only to this service; nothing may frame it.
constexpr const char* kContentSecurityPolicy =
    "default-src 'self'; img-src 'self' data: blob:; style-src 'self' 'unsafe-inline'; "
    "object-src 'none'; base-uri 'none'; frame-ancestors 'none'";

bool allowed_segment(std::string_view segment) {
    // '.', '..' and dotfiles; a backslash or NUL could mean something else to the file system.
    return !segment.empty() && segment.front() != '.' &&
           segment.find_first_of(std::string_view("\\\0", 2)) == std::string_view::npos;
}

bool inside(const fs::path& root, const fs::path& file) {
    const auto [r, f] = std::mismatch(root.begin(), root.end(), file.begin(), file.end());
    return r == root.end();
}

std::optional<std::string> read_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return std::move(text).str();
}

Response missing(const Request& request) {
    return error_response(request, http::status::not_found, "not_found",
                          "no such resource: " + std::string(request.target()));
}

}  // namespace

std::optional<fs::path> static_file_path(const fs::path& root, std::string_view url_path) {
    const std::string decoded = percent_decode(url_path, /*plus_is_space=*/false);
    fs::path file = root;
    std::string_view rest = decoded;
    std::string_view last;
    while (!rest.empty()) {
        const std::size_t slash = rest.find('/');
        const std::string_view segment = rest.substr(0, slash);
        rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
        if (segment.empty()) continue;  // "//" and the leading "/"
        if (!allowed_segment(segment)) return std::nullopt;
        file /= fs::path(std::string(segment));
        last = segment;
    }
    if (last.empty() || decoded.back() == '/') file /= "index.html";
    return file;
}

const char* static_content_type(const fs::path& file) {
    static const std::pair<const char*, const char*> types[] = {
        {".html", "text/html; charset=utf-8"},
        {".js", "text/javascript; charset=utf-8"},
        {".mjs", "text/javascript; charset=utf-8"},
        {".css", "text/css; charset=utf-8"},
        {".json", "application/json"},
        {".map", "application/json"},
        {".svg", "image/svg+xml"},
        {".png", "image/png"},
        {".ico", "image/x-icon"},
        {".woff2", "font/woff2"},
        {".wasm", "application/wasm"},
        {".glb", "model/gltf-binary"},
        {".txt", "text/plain; charset=utf-8"},
        // The example scenes' own files, fetched by the viewer to inline them.
        {".ies", "text/plain; charset=utf-8"},
        {".ldt", "text/plain; charset=utf-8"},
        {".obj", "text/plain; charset=utf-8"},
        {".mtl", "text/plain; charset=utf-8"},
    };
    const std::string extension = file.extension().string();
    for (const auto& [ext, type] : types) {
        if (extension == ext) return type;
    }
    return "application/octet-stream";
}

StaticFiles::StaticFiles(fs::path root) : root_(std::move(root)) {}

bool StaticFiles::installed() const {
    std::error_code ec;
    return !root_.empty() && fs::is_regular_file(root_ / "index.html", ec);
}

Response StaticFiles::serve(const Request& request, std::string_view url_path) const {
    if (root_.empty()) return missing(request);
    const std::optional<fs::path> file = static_file_path(root_, url_path);
    if (!file) return missing(request);
    // Symbolic links are followed only while they stay inside the root.
    std::error_code ec;
    const fs::path real_root = fs::canonical(root_, ec);
    if (ec) return missing(request);
    const fs::path real_file = fs::canonical(*file, ec);
    if (ec || !inside(real_root, real_file) || !fs::is_regular_file(real_file, ec)) {
        return missing(request);
    }
    std::optional<std::string> body = read_file(real_file);
    if (!body) return missing(request);
    const std::size_t size = body->size();
    const bool head = request.method() == http::verb::head;
    Response response =
        text_response(request, http::status::ok, head ? std::string() : std::move(*body),
                      static_content_type(real_file));
    if (head) response.content_length(size);
    response.set(http::field::cache_control, "no-cache");
    response.set("X-Content-Type-Options", "nosniff");
    response.set("Content-Security-Policy", kContentSecurityPolicy);
    return response;
}

}  // namespace radiant::server
