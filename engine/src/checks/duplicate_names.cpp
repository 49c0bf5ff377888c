#include "checks/duplicate_names.h"

#include <unordered_map>

#include "checks/warning_text.h"

namespace radiant {
namespace {

/// Reports each name whose first use was at another document pointer.
template <typename Item, typename PointerOf>
void report_repeats(const std::vector<Item>& items, const char* what, PointerOf pointer_of,
                    std::vector<Warning>& out) {
    std::unordered_map<std::string, std::string> first;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string pointer = pointer_of(i);
        const auto [it, inserted] = first.emplace(items[i].name, pointer);
        if (inserted || it->second == pointer) continue;
        out.push_back({"duplicate_name",
                       std::string(what) + " name " + quoted(items[i].name) + " is also used by " +
                           it->second + ": their results cannot be told apart",
                       pointer + "/name"});
    }
}

}  // namespace

void check_duplicate_names(const Scene& scene, std::vector<Warning>& out) {
    report_repeats(
        scene.surfaces, "surface", [&](std::size_t i) { return surface_pointer(scene, i); }, out);
    report_repeats(
        scene.luminaires, "luminaire",
        [](std::size_t i) { return "/luminaires/" + std::to_string(i); }, out);
    report_repeats(
        scene.sensors, "sensor set", [](std::size_t i) { return "/sensors/" + std::to_string(i); },
        out);
}

}  // namespace radiant
