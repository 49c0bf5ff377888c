#include "radiant/mesh_ray_caster.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "radiant/box.h"
#include "visibility/visibility.h"

namespace radiant {
namespace {

Vec3 bounding_box_centre(const std::vector<Vec3>& points) {
    return points.empty() ? Vec3{} : bounding_box(points).centre();
}

}  // namespace

MeshRayCaster::MeshRayCaster(const SolvedMesh& mesh) : centre_(bounding_box_centre(mesh.vertices)) {
    std::vector<Triangle> triangles;
    triangles.reserve(mesh.triangles.size());
    const auto local = [&](int v) { return mesh.vertices[static_cast<std::size_t>(v)] - centre_; };
    for (const auto& t : mesh.triangles)
        triangles.push_back({local(t[0]), local(t[1]), local(t[2])});
    visibility_ = make_embree_visibility(triangles);
}

MeshRayCaster::~MeshRayCaster() = default;

std::optional<MeshRayCaster::Hit> MeshRayCaster::intersect(const Vec3& origin,
                                                           const Vec3& direction) const {
    const RayHit hit = visibility_->intersect(origin - centre_, direction,
                                              std::numeric_limits<double>::infinity());
    if (hit.triangle < 0) return std::nullopt;
    return Hit{hit.triangle, hit.t};
}

}  // namespace radiant
