#include "checks/duplicate_names.h"

#include <unordered_map>

#include "checks/warning_text.h"

namespace radiant {
namespace {

/// One warning per name used at more than one document pointer, at its second use: a model
/// with 600 surfaces named "book" made one naming choice, not 599 mistakes.
template <typename Item, typename PointerOf>
void report_repeats(const std::vector<Item>& items, const char* what, PointerOf pointer_of,
                    std::vector<Warning>& out) {
    struct Uses {
        std::string first, second, last;
        std::size_t count = 0;  // distinct pointers
    };
    std::unordered_map<std::string, Uses> uses;
    std::vector<std::string> repeated;  // in the order of their second use
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string pointer = pointer_of(i);
        Uses& u = uses[items[i].name];
        if (u.count > 0 && u.last == pointer) continue;  // an imported model's parts
        if (u.count == 0) u.first = pointer;
        if (u.count == 1) {
            u.second = pointer;
            repeated.push_back(items[i].name);
        }
        u.last = pointer;
        ++u.count;
    }
    for (const std::string& name : repeated) {
        const Uses& u = uses.at(name);
        const std::string others =
            u.count > 2 ? " and " + std::to_string(u.count - 2) + " more" : std::string();
        out.push_back({"duplicate_name",
                       std::string(what) + " name " + quoted(name) + " is also used by " + u.first +
                           others + ": their results cannot be told apart",
                       u.second + "/name"});
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
