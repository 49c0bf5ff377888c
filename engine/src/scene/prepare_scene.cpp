#include "radiant/box.h"
#include "scene/prepared_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "formfactor/quadrature.h"
#include "geometry/polygon_split.h"

namespace radiant {
namespace {

struct RawPolygon {
    std::vector<Vec3> vertices;  // world metres
    int surface;
    int material;
};

// The six faces of an axis-aligned box, counter-clockwise about the requested normal.
std::vector<std::vector<Vec3>> box_faces(const Vec3& lo, const Vec3& hi, bool facing_in) {
    std::vector<std::vector<Vec3>> faces;
    for (int axis = 0; axis < 3; ++axis) {
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            Vec3 outward{};
            outward[axis] = side == 0 ? -1.0 : 1.0;
            const Vec3 wanted = facing_in ? -outward : outward;
            std::vector<Vec3> quad(4);
            const double c = side == 0 ? lo[axis] : hi[axis];
            const double u[4] = {lo[a1], hi[a1], hi[a1], lo[a1]};
            const double v[4] = {lo[a2], lo[a2], hi[a2], hi[a2]};
            for (int k = 0; k < 4; ++k) {
                quad[k][axis] = c;
                quad[k][a1] = u[k];
                quad[k][a2] = v[k];
            }
            if (dot(cross(quad[1] - quad[0], quad[2] - quad[0]), wanted) < 0) {
                std::reverse(quad.begin(), quad.end());
            }
            faces.push_back(std::move(quad));
        }
    }
    return faces;
}

std::vector<Vec3> scaled(const std::vector<Vec3>& points, double s) {
    std::vector<Vec3> out;
    out.reserve(points.size());
    for (const Vec3& p : points) out.push_back(p * s);
    return out;
}

std::vector<RawPolygon> raw_polygons(const Scene& scene, const std::vector<int>& material_of) {
    const double s = meters_per_unit(scene.units);
    std::vector<RawPolygon> raw;
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        const Surface& surface = scene.surfaces[i];
        const int si = static_cast<int>(i);
        const int mi = material_of[i];
        if (const auto* polygon = std::get_if<Polygon>(&surface.geometry)) {
            raw.push_back({scaled(*polygon, s), si, mi});
        } else if (const auto* mesh = std::get_if<MeshGeometry>(&surface.geometry)) {
            for (const auto& face : mesh->faces) {
                std::vector<Vec3> v;
                for (const int k : face)
                    v.push_back(mesh->vertices[static_cast<std::size_t>(k)] * s);
                raw.push_back({std::move(v), si, mi});
            }
        } else {
            const auto& box = std::get<BoxGeometry>(surface.geometry);
            for (auto& face : box_faces(box.min * s, box.max * s, box.facing_in)) {
                raw.push_back({std::move(face), si, mi});
            }
        }
    }
    return raw;
}

bool is_gray(const Rgb& c) { return c[0] == c[1] && c[1] == c[2]; }

// Emission and luminaire colours are relative: scaled so that their luminance is 1.
Rgb normalized_color(const std::optional<Rgb>& color) {
    if (!color) return {1, 1, 1};
    const double y = luminance(*color);
    if (!(y > 0)) return {1, 1, 1};
    return {(*color)[0] / y, (*color)[1] / y, (*color)[2] / y};
}

// The C0 plane of a luminaire aimed at `aim`: the x axis for a luminaire aimed straight down,
// carried along by the smallest rotation that turns straight down to `aim`, then turned by
// `rotation_deg` towards C90 (counter-clockwise seen from behind the luminaire).
Vec3 c0_axis(const Vec3& aim, double rotation_deg) {
    const Vec3 down{0, 0, -1}, x{1, 0, 0};
    const double c = dot(down, aim);
    Vec3 c0 = c < -1 + 1e-12 ? x
                             : x + cross(cross(down, aim), x) +
                                   cross(cross(down, aim), cross(cross(down, aim), x)) / (1 + c);
    c0 = normalized(c0 - aim * dot(aim, c0));
    const Vec3 c90 = cross(c0, aim);
    const double r = rotation_deg * std::numbers::pi / 180;
    return normalized(c0 * std::cos(r) + c90 * std::sin(r));
}

SensorGrid grid_in_meters(SensorGrid grid, double meters_per_unit) {
    grid.spacing *= meters_per_unit;
    grid.origin = grid.origin * meters_per_unit;
    grid.u = grid.u * meters_per_unit;
    grid.v = grid.v * meters_per_unit;
    for (Vec3& x : grid.points) x = x * meters_per_unit;
    return grid;
}

}  // namespace

PreparedScene prepare_scene(const Scene& scene) {
    PreparedScene out;
    out.name = scene.name;

    std::unordered_map<std::string, int> material_index;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        material_index[scene.materials[i].name] = static_cast<int>(i);
    }
    std::vector<int> material_of;
    for (const Surface& s : scene.surfaces) {
        out.surface_names.push_back(s.name);
        const auto it = material_index.find(s.material);
        material_of.push_back(it == material_index.end() ? 0 : it->second);
    }

    const std::vector<RawPolygon> raw = raw_polygons(scene, material_of);

    Box box;
    for (const RawPolygon& p : raw) box.add(p.vertices);
    if (box.empty()) box = {Vec3{}, Vec3{}};
    out.world_origin = box.centre();
    out.diagonal_m = length(box.size());

    // Pieces in the local frame. Polygons that are not convex or not planar to 1e-9 of the scene
    // become triangles, each planar by construction.
    const double planarity = 1e-9 * out.diagonal_m;
    const double min_area = 1e-14 * out.diagonal_m * out.diagonal_m;
    out.surface_area_m2.assign(scene.surfaces.size(), 0.0);
    std::vector<double> material_area(scene.materials.size(), 0.0);
    for (const RawPolygon& p : raw) {
        std::vector<Vec3> local;
        for (const Vec3& v : p.vertices) local.push_back(v - out.world_origin);
        const Vec3 n = polygon_normal(local);
        if (length(n) == 0) continue;
        for (auto& piece : convex_pieces(simplify_polygon(local, planarity), n, planarity)) {
            const double area = polygon_area(piece);
            const Vec3 pn = polygon_normal(piece);
            if (area <= min_area || length(pn) == 0) continue;
            out.surface_area_m2[static_cast<std::size_t>(p.surface)] += area;
            material_area[static_cast<std::size_t>(p.material)] += area;
            out.total_area_m2 += area;
            out.pieces.push_back({std::move(piece), pn, area, p.surface, p.material});
        }
    }

    out.components = light_components(scene);
    bool gray = true;
    for (const Material& m : scene.materials) {
        gray = gray && is_gray(m.reflectance);
        if (m.emission) gray = gray && is_gray(normalized_color(m.emission->color));
    }
    for (const Luminaire& l : scene.luminaires) gray = gray && is_gray(normalized_color(l.color));
    out.channels = gray ? 1 : 3;

    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        PreparedMaterial pm;
        pm.name = m.name;
        pm.reflectance = m.reflectance;
        pm.two_sided = m.two_sided;
        pm.component = std::max(0, out.components.material_component[i]);
        if (m.emission && m.emission->value > 0) {
            double exitance = m.emission->value;
            if (m.emission->kind == Emission::Kind::flux) {
                exitance = material_area[i] > 0 ? m.emission->value / material_area[i] : 0.0;
            }
            const Rgb c = normalized_color(m.emission->color);
            for (int k = 0; k < 3; ++k) pm.exitance_lm_m2[k] = exitance * c[k];
        }
        out.materials.push_back(std::move(pm));
    }

    const double s = meters_per_unit(scene.units);
    for (std::size_t i = 0; i < scene.luminaires.size(); ++i) {
        const Luminaire& l = scene.luminaires[i];
        PreparedLuminaire pl;
        pl.name = l.name;
        pl.component = out.components.luminaire_component[i];
        pl.position = l.position * s - out.world_origin;
        const Rgb c = normalized_color(l.color);
        pl.distribution = l.distribution;
        pl.aim = normalized(l.aim);
        double flux_lm = l.flux_lm.value_or(0);
        if (l.distribution == Distribution::photometric && l.photometry) {
            pl.table = std::make_shared<const IntensityTable>(*l.photometry);
            flux_lm = l.flux_lm.value_or(pl.table->flux_lm());
            pl.c0_axis = c0_axis(pl.aim, l.rotation_deg);
            pl.c90_axis = cross(pl.c0_axis, pl.aim);
            pl.luminous = l.photometry->luminous;
        } else {
            // The C0 axis of a table-less luminaire still orients its luminous area.
            pl.c0_axis = c0_axis(pl.aim, l.rotation_deg);
            pl.c90_axis = cross(pl.c0_axis, pl.aim);
        }
        if (l.luminous_area) {
            pl.luminous = *l.luminous_area;
            pl.luminous.length *= s;
            pl.luminous.width *= s;
            pl.luminous.height *= s;
        }
        for (int k = 0; k < 3; ++k) pl.flux_lm[k] = flux_lm * c[k];
        out.luminaires.push_back(std::move(pl));
    }
    for (const SensorSet& set : scene.sensors) {
        PreparedSensorSet ps;
        ps.name = set.name;
        for (const Vec3& p : set.points) ps.points.push_back(p * s - out.world_origin);
        ps.kind = set.kind;
        ps.normal = normalized(set.normal);
        // The vertical kinds face the horizontal part of the normal.
        if (set.kind == SensorKind::vertical || set.kind == SensorKind::semi_cylindrical)
            ps.normal = normalized(Vec3{set.normal.x, set.normal.y, 0});
        if (set.grid) ps.grid = grid_in_meters(*set.grid, s);
        out.sensors.push_back(std::move(ps));
    }
    for (const Observer& o : scene.observers)
        out.observers.push_back({o.name, o.position * s - out.world_origin, normalized(o.view)});
    return out;
}

}  // namespace radiant
