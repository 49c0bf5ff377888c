#include "solution/gouraud.h"

#include <algorithm>

namespace radiant {

SolvedMesh gouraud_mesh(const PatchMesh& patches, const std::vector<double>& value,
                        const Vec3& world_origin) {
    const PolyMesh& mesh = patches.mesh();
    const std::size_t nv = mesh.n_vertices();

    // Interior vertices: area-weighted mean of the faces around them.
    std::vector<double> vertex_value(nv, 0.0);
    std::vector<bool> interior(nv, false);
    for (const auto vh : mesh.vertices()) {
        const auto v = static_cast<std::size_t>(vh.idx());
        interior[v] = !mesh.is_boundary(vh);
        double sum = 0, area = 0;
        for (const auto fh : mesh.vf_range(vh)) {
            const auto f = static_cast<std::size_t>(fh.idx());
            sum += patches.patch(f).area_m2 * value[f];
            area += patches.patch(f).area_m2;
        }
        vertex_value[v] = area > 0 ? sum / area : 0;
    }
    // Boundary vertices: B_v = 2·B_f − B_inner, with B_inner the mean of f's interior vertices,
    // averaged over the faces at v and clamped at 0 (extrapolation may overshoot).
    std::vector<double> boundary_value(nv, 0.0);
    for (const auto vh : mesh.vertices()) {
        const auto v = static_cast<std::size_t>(vh.idx());
        if (interior[v]) continue;
        double sum = 0;
        int count = 0;
        for (const auto fh : mesh.vf_range(vh)) {
            const auto f = static_cast<std::size_t>(fh.idx());
            double inner = 0;
            int inner_count = 0;
            for (const auto wh : mesh.fv_range(fh)) {
                if (interior[static_cast<std::size_t>(wh.idx())]) {
                    inner += vertex_value[static_cast<std::size_t>(wh.idx())];
                    ++inner_count;
                }
            }
            sum += inner_count > 0 ? 2 * value[f] - inner / inner_count : value[f];
            ++count;
        }
        boundary_value[v] = count > 0 ? std::max(0.0, sum / count) : 0.0;
    }

    SolvedMesh out;
    out.vertices.reserve(nv);
    out.vertex_radiosity.reserve(nv);
    for (const auto vh : mesh.vertices()) {
        const auto& p = mesh.point(vh);
        out.vertices.push_back(Vec3{p[0], p[1], p[2]} + world_origin);
        const auto v = static_cast<std::size_t>(vh.idx());
        out.vertex_radiosity.push_back(interior[v] ? vertex_value[v] : boundary_value[v]);
    }
    for (const auto fh : mesh.faces()) {
        std::vector<int> corners;
        for (const auto vh : mesh.fv_range(fh)) corners.push_back(vh.idx());
        const auto f = static_cast<std::size_t>(fh.idx());
        for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
            out.triangles.push_back({corners[0], corners[k], corners[k + 1]});
            out.triangle_surface.push_back(patches.patch(f).surface);
            out.triangle_radiosity.push_back(value[f]);
        }
    }
    return out;
}

}  // namespace radiant
