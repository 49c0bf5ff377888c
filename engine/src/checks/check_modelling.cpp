// The public entry points of the modelling checks (radiant/warnings.h).
#include <sstream>

#include "checks/modelling_checks.h"
#include "visibility/occluder_triangles.h"

namespace radiant {

std::vector<Warning> check_modelling(const Scene& scene) {
    const PreparedScene prepared = prepare_scene(scene);
    // Nothing to look at: solve() refuses such a scene with its own error.
    if (prepared.pieces.empty()) return {};
    const auto [triangles, triangle_piece] = occluder_triangles(prepared);
    const std::unique_ptr<Visibility> visibility = make_embree_visibility(triangles);
    std::uint64_t rays = 0;
    return modelling_warnings({scene, prepared, *visibility, triangles, triangle_piece, 1}, rays);
}

std::string describe_warnings(const std::vector<Warning>& warnings) {
    std::ostringstream out;
    for (std::size_t i = 0; i < warnings.size(); ++i) {
        if (i) out << "; ";
        out << warnings[i].code << ": " << warnings[i].pointer << ": " << warnings[i].message;
    }
    return out.str();
}

}  // namespace radiant
