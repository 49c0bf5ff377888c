#include "hierarchy/leaf_mesh.h"

#include <cmath>
#include <map>
#include <tuple>

#include "solution/surface_summary.h"

namespace radiant {

SolvedMesh leaf_mesh(const ElementTree& tree, const PatchMesh& patches, int channels,
                     const Vec3& world_origin) {
    std::vector<double> radiosity(tree.size(), 0.0);
    for (std::size_t e = 0; e < tree.size(); ++e)
        radiosity[e] = photometric(tree[e].radiosity, channels);
    return leaf_mesh(tree, patches, radiosity, world_origin);
}

SolvedMesh leaf_mesh(const ElementTree& tree, const PatchMesh& patches,
                     std::span<const double> radiosity, const Vec3& world_origin) {
    SolvedMesh mesh;
    // Vertices are shared within one plane of one surface side: midpoints of shared edges are
    // computed alike on both sides, so exact coordinates match.
    using Key =
        std::tuple<int, bool, std::tuple<long long, long long, long long>, double, double, double>;
    std::map<Key, int> index;
    std::vector<double> weight;
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (x.cluster || !x.leaf()) continue;
        const PatchGeometry& p = patches.patch(static_cast<std::size_t>(x.patch));
        const double b = radiosity[e];
        const auto plane =
            std::make_tuple(std::llround(x.normal.x * 1e9), std::llround(x.normal.y * 1e9),
                            std::llround(x.normal.z * 1e9));
        std::vector<int> corners;
        for (const Vec3& v : x.polygon) {
            const Key key{p.surface, p.back_side, plane, v.x, v.y, v.z};
            auto it = index.find(key);
            if (it == index.end()) {
                it = index.emplace(key, static_cast<int>(mesh.vertices.size())).first;
                mesh.vertices.push_back(v + world_origin);
                mesh.vertex_radiosity.push_back(0);
                weight.push_back(0);
            }
            const auto k = static_cast<std::size_t>(it->second);
            mesh.vertex_radiosity[k] += x.area_m2 * b;
            weight[k] += x.area_m2;
            corners.push_back(it->second);
        }
        for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
            mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
            mesh.triangle_surface.push_back(p.surface);
            mesh.triangle_radiosity.push_back(b);
        }
    }
    for (std::size_t k = 0; k < weight.size(); ++k) {
        if (weight[k] > 0) mesh.vertex_radiosity[k] /= weight[k];
    }
    return mesh;
}

}  // namespace radiant
