// Helpers shared by tests that read files from the source tree.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace radiant::test {

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

/// The *.json files of `dir`, sorted, except expected.json (test expectations, not scenes).
inline std::vector<std::filesystem::path> json_files(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() == ".json" && entry.path().filename() != "expected.json") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// Every scene that must be accepted: tests/data/good, the examples (with the furnished office
/// and its model and photometric files, and the generated cluttered office), the validation
/// scenes and the box rooms.
inline std::vector<std::filesystem::path> good_scenes() {
    const std::filesystem::path data = RADIANT_TEST_DATA;
    std::vector<std::filesystem::path> files = json_files(data / "good");
    for (const auto& dir : {std::filesystem::path(RADIANT_SOURCE_DIR) / "proto/examples",
                            data / "scenes", data / "box_rooms"}) {
        const auto more = json_files(dir);
        files.insert(files.end(), more.begin(), more.end());
    }
    files.push_back(data / "radiance/room-s2.json");
    files.push_back(std::filesystem::path(RADIANT_SOURCE_DIR) /
                    "proto/examples/furnished-office/furnished-office.json");
    files.push_back(std::filesystem::path(RADIANT_SOURCE_DIR) /
                    "proto/examples/furnished-office-clutter/furnished-office.json");
    return files;
}

}  // namespace radiant::test
