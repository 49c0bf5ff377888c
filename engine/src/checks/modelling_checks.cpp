#include "checks/modelling_checks.h"

#include <algorithm>

#include "checks/black_backs.h"
#include "checks/duplicate_names.h"
#include "checks/emission_checks.h"
#include "checks/light_paths.h"
#include "checks/luminaire_placement.h"
#include "checks/sensor_placement.h"
#include "checks/units_check.h"

namespace radiant {

Box model_bounds(const PreparedScene& prepared) {
    Box box;
    for (const Piece& p : prepared.pieces) box.add(p.vertices);
    return box;
}

double distance_outside(const Box& box, const Vec3& x) {
    double d = 0;
    for (int a = 0; a < 3; ++a) d = std::max({d, box.lo[a] - x[a], x[a] - box.hi[a]});
    return d;
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

std::vector<Warning> modelling_warnings(const CheckedScene& input, std::uint64_t& rays) {
    std::vector<Warning> out;
    check_duplicate_names(input.scene, out);
    check_units(input.scene, input.prepared, out);
    check_emission(input.scene, input.prepared, out);
    const LightPaths paths = trace_light_paths(input, rays);
    const std::vector<bool> misplaced = check_luminaire_placement(input, paths, out);
    check_black_backs(input, paths, misplaced, out);
    check_sensor_placement(input, out, rays);
    return out;
}

}  // namespace radiant
