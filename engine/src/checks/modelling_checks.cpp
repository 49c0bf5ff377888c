#include "checks/modelling_checks.h"

#include <algorithm>
#include <unordered_map>

#include "checks/black_backs.h"
#include "checks/duplicate_names.h"
#include "checks/emission_checks.h"
#include "checks/emitter_placement.h"
#include "checks/light_paths.h"
#include "checks/luminaire_placement.h"
#include "checks/sensor_facing.h"
#include "checks/sensor_placement.h"
#include "checks/units_check.h"
#include "checks/up_axis_check.h"

namespace radiant {
namespace {

// Warnings of one code past this many are summed up in one more: 776 boxes facing in are one
// mistake to fix, and a result or an error listing each of them hides every other warning.
constexpr std::size_t kMaxWarningsPerCode = 20;

/// Keeps the first kMaxWarningsPerCode warnings of each code; the next one, at its own pointer,
/// says how many more there were.
std::vector<Warning> capped_per_code(std::vector<Warning> all) {
    std::unordered_map<std::string, std::size_t> count;
    for (const Warning& w : all) ++count[w.code];
    std::unordered_map<std::string, std::size_t> seen;
    std::vector<Warning> out;
    for (Warning& w : all) {
        const std::size_t k = ++seen[w.code];
        if (k <= kMaxWarningsPerCode) {
            out.push_back(std::move(w));
        } else if (k == kMaxWarningsPerCode + 1) {
            const std::size_t more = count[w.code] - kMaxWarningsPerCode;
            out.push_back({w.code,
                           std::to_string(more) + " more " + w.code +
                               " warnings are not listed; the first of them: " + w.message,
                           w.pointer});
        }
    }
    return out;
}

}  // namespace

Box model_bounds(const PreparedScene& prepared) {
    Box box;
    for (const Piece& p : prepared.pieces) box.add(p.vertices);
    return box;
}

bool is_room_sized(const Vec3& size, const Box& model) {
    const auto volume = [](const Vec3& v) { return v.x * v.y * v.z; };
    return volume(size) >= 0.5 * volume(model.size());
}

double distance_outside(const Box& box, const Vec3& x) {
    double d = 0;
    for (int a = 0; a < 3; ++a) d = std::max({d, box.lo[a] - x[a], x[a] - box.hi[a]});
    return d;
}

std::size_t stride_for(std::size_t count, std::size_t most) {
    return std::max<std::size_t>(1, (count + most - 1) / most);
}

EmittedLight emitted_light(const PreparedScene& prepared) {
    EmittedLight out;
    for (const PreparedLuminaire& l : prepared.luminaires)
        out.luminaires_lm += luminance(l.flux_lm);
    for (const Piece& p : prepared.pieces) {
        out.surfaces_lm +=
            luminance(prepared.materials[static_cast<std::size_t>(p.material)].exitance_lm_m2) *
            p.area_m2;
    }
    return out;
}

double mean_surface_lux(const PreparedScene& prepared, const EmittedLight& emitted) {
    return prepared.total_area_m2 > 0 ? emitted.total_lm() / prepared.total_area_m2 : 0.0;
}

std::vector<Warning> modelling_warnings(const CheckedScene& input, std::uint64_t& rays) {
    std::vector<Warning> out;
    check_duplicate_names(input.scene, out);
    check_units(input.scene, input.prepared, out);
    check_up_axis(input.scene, input.prepared, out);
    check_emission(input.scene, input.prepared, out);
    const LightPaths paths = trace_light_paths(input, rays);
    const std::vector<bool> misplaced = check_luminaire_placement(input, paths, out);
    const std::vector<bool> misplaced_emitters = check_emitter_placement(input, out, rays);
    check_black_backs(input, paths, misplaced, misplaced_emitters, out);
    const std::vector<bool> misplaced_sensors = check_sensor_placement(input, out, rays);
    check_sensor_facing(input, misplaced_sensors, out, rays);
    return capped_per_code(std::move(out));
}

}  // namespace radiant
