#include "import/scene_relative_file.h"

#include <fstream>

namespace radiant::proto {

std::optional<std::string> read_scene_relative_file(
    const std::optional<std::filesystem::path>& scene_directory, const std::string& name,
    std::size_t max_bytes, std::string& bytes) {
    if (!scene_directory) {
        return "a file reference needs a scene file (radiant validate/solve SCENE.json); inline "
               "the file's content instead";
    }
    const std::filesystem::path path = *scene_directory / name;
    auto problem = [&](const std::string& why) {
        return "cannot read " + path.string() + ": " + why;
    };
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return problem(ec.message());
    if (size > max_bytes)
        return problem("over the limit of " + std::to_string(max_bytes) + " bytes");
    std::ifstream in(path, std::ios::binary);
    bytes.assign(static_cast<std::size_t>(size), '\0');
    if (!in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        return problem("read error");
    return std::nullopt;
}

}  // namespace radiant::proto
