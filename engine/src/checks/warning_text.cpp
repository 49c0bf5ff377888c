#include "checks/warning_text.h"

#include <cmath>
#include <cstdio>

namespace radiant {

std::string surface_pointer(const Scene& scene, std::size_t index) {
    const std::string& pointer = scene.surfaces[index].pointer;
    return pointer.empty() ? "/surfaces/" + std::to_string(index) : pointer;
}

std::string surface_label(const Scene& scene, std::size_t index) {
    return "surface " + quoted(scene.surfaces[index].name) + " (" + surface_pointer(scene, index) +
           ")";
}

std::string quoted(const std::string& name) { return "\"" + name + "\""; }

std::string percent(double share) {
    if (share < 0.01) return "under 1 %";
    return std::to_string(static_cast<int>(std::lround(100 * share))) + " %";
}

std::string length_text(double meters) {
    struct Unit {
        double meters;
        const char* name;
    };
    static constexpr Unit kUnits[] = {{1e3, "km"}, {1, "m"}, {1e-2, "cm"}, {1e-3, "mm"}};
    const double m = std::abs(meters);
    const Unit* unit = &kUnits[3];
    for (const Unit& u : kUnits) {
        if (m >= u.meters) {
            unit = &u;
            break;
        }
    }
    // Two significant figures, without an exponent for values up to 1000 of the unit.
    const double value = meters / unit->meters;
    char text[48];
    std::snprintf(text, sizeof text, std::abs(value) >= 100 ? "%.0f %s" : "%.2g %s", value,
                  unit->name);
    return text;
}

std::string point_text(const Vec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x, p.y, p.z);
    return text;
}

}  // namespace radiant
