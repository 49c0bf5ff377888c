#include "bench_scenes.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <variant>

#include "furnished_office_scene.h"
#include "office_scene.h"
#include "photometry/ies_reader.h"

namespace radiant::bench {
namespace {

constexpr const char* kOfficePrefix = "office-x";
constexpr const char* kFloorPrefix = "furnished-floor-x";

// The number after `prefix` in `name` ("office-x16" → 16), or 0.
int units_after(const std::string& name, const std::string& prefix) {
    if (name.rfind(prefix, 0) != 0) return 0;
    const std::string digits = name.substr(prefix.size());
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    if (digits.empty() || !std::all_of(digits.begin(), digits.end(), digit)) return 0;
    return std::stoi(digits);
}

bool listed(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

const std::vector<std::string>& office_series() {
    static const std::vector<std::string> names{"office-x1", "office-x4", "office-x16",
                                                "office-x64"};
    return names;
}

const std::vector<std::string>& clutter_scenes() {
    static const std::vector<std::string> names{"furnished-office", "furnished-office-ies"};
    return names;
}

const std::vector<std::string>& clutter_series() {
    static const std::vector<std::string> names{"furnished-office", "furnished-floor-x4",
                                                "furnished-floor-x16", "furnished-floor-x64"};
    return names;
}

bool is_generated_scene(const std::string& name) {
    return listed(office_series(), name) || listed(clutter_scenes(), name) ||
           listed(clutter_series(), name);
}

std::optional<Scene> generated_scene(const std::string& name,
                                     const std::filesystem::path& downlight_ies, std::string& why) {
    if (!is_generated_scene(name)) {
        why = "unknown generated scene " + name;
        return std::nullopt;
    }
    if (const int units = units_after(name, kOfficePrefix)) return furnished_office(units);
    if (const int rooms = units_after(name, kFloorPrefix)) return furnished_floor(rooms);
    if (name == "furnished-office") return furnished_office_clutter();
    std::ifstream in(downlight_ies);
    if (!in) {
        why = "cannot read " + downlight_ies.string();
        return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    auto table = proto::read_ies(text.str());
    if (const auto* message = std::get_if<std::string>(&table)) {
        why = downlight_ies.string() + ": " + *message;
        return std::nullopt;
    }
    return furnished_office_ies(std::get<PhotometricTable>(table));
}

}  // namespace radiant::bench
