// EN 12464-1 work-plane grids over named floors (expand_workplanes, declared in radiant/scene.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "formfactor/quadrature.h"
#include "radiant/box.h"
#include "radiant/scene.h"

namespace radiant {
namespace {

// A face counts as a horizontal floor when its normal is this close to straight up.
constexpr double kUpwardCosine = 1 - 1e-6;
// The usual desk height and wall zone (EN 12464-1 leaves 0.5 m along the walls).
constexpr double kDefaultHeightM = 0.8, kDefaultBorderM = 0.5;

struct Point2 {
    double u = 0, v = 0;
};

/// A floor face in the plane's (u, v) coordinates, with its height.
struct FloorFace {
    std::vector<Point2> corners;
    double z = 0;
};

struct Edge {
    Vec3 a, b;
};

std::vector<std::vector<Vec3>> faces_of(const Surface& s) {
    if (const auto* polygon = std::get_if<Polygon>(&s.geometry)) return {*polygon};
    if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
        std::vector<std::vector<Vec3>> out;
        for (const auto& face : mesh->faces) {
            auto& corners = out.emplace_back();
            for (const int k : face) corners.push_back(mesh->vertices[static_cast<std::size_t>(k)]);
        }
        return out;
    }
    // A room's floor faces up from its bottom, an object's top from its lid.
    const auto& box = std::get<BoxGeometry>(s.geometry);
    const double z = box.facing_in ? box.min.z : box.max.z;
    return {{{box.min.x, box.min.y, z},
             {box.max.x, box.min.y, z},
             {box.max.x, box.max.y, z},
             {box.min.x, box.max.y, z}}};
}

bool same_point(const Vec3& a, const Vec3& b, double tolerance) {
    return length_squared(a - b) <= tolerance * tolerance;
}

/// Edges of `faces` that no other face shares in the opposite direction: the outline. Edges
/// are sorted by their end's x, so each looks only at those whose end is within `tolerance` of
/// its start in x (a plant of 3,000 triangles: 9,000 edges, not 81 million pairs).
std::vector<Edge> outline(const std::vector<std::vector<Vec3>>& faces, double tolerance) {
    std::vector<Edge> edges;
    for (const auto& f : faces) {
        for (std::size_t k = 0; k < f.size(); ++k) edges.push_back({f[k], f[(k + 1) % f.size()]});
    }
    std::vector<Edge> by_end = edges;
    std::sort(by_end.begin(), by_end.end(),
              [](const Edge& p, const Edge& q) { return p.b.x < q.b.x; });
    std::vector<Edge> out;
    for (const Edge& e : edges) {
        auto o = std::lower_bound(by_end.begin(), by_end.end(), e.a.x - tolerance,
                                  [](const Edge& p, double x) { return p.b.x < x; });
        bool shared = false;
        for (; o != by_end.end() && o->b.x <= e.a.x + tolerance && !shared; ++o) {
            shared = same_point(e.a, o->b, tolerance) && same_point(e.b, o->a, tolerance);
        }
        if (!shared) out.push_back(e);
    }
    return out;
}

bool inside_polygon(const std::vector<Point2>& polygon, Point2 p) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2 a = polygon[i], b = polygon[j];
        if ((a.v > p.v) != (b.v > p.v) && p.u < (b.u - a.u) * (p.v - a.v) / (b.v - a.v) + a.u) {
            inside = !inside;
        }
    }
    return inside;
}

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
    const double du = b.u - a.u, dv = b.v - a.v;
    const double length2 = du * du + dv * dv;
    const double t =
        length2 > 0 ? std::clamp(((p.u - a.u) * du + (p.v - a.v) * dv) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(p.u - a.u - t * du, p.v - a.v - t * dv);
}

/// A closed mesh with outward faces: furniture. Points inside it are not on the work plane.
struct Solid {
    std::vector<std::vector<Vec3>> faces;
    Vec3 lo, hi;

    /// Parity of the faces crossed by the upward ray from x.
    bool contains(const Vec3& x) const {
        if (x.x < lo.x || x.x > hi.x || x.y < lo.y || x.y > hi.y || x.z < lo.z || x.z > hi.z) {
            return false;
        }
        bool inside = false;
        for (const auto& f : faces) {
            const Vec3 n = polygon_normal(f);
            if (std::abs(n.z) < 1e-12) continue;
            const double z = f[0].z - ((x.x - f[0].x) * n.x + (x.y - f[0].y) * n.y) / n.z;
            if (z <= x.z) continue;
            std::vector<Point2> flat;
            for (const Vec3& c : f) flat.push_back({c.x, c.y});
            if (inside_polygon(flat, {x.x, x.y})) inside = !inside;
        }
        return inside;
    }
};

double signed_volume(const std::vector<std::vector<Vec3>>& faces) {
    double v = 0;
    for (const auto& f : faces) {
        for (std::size_t k = 1; k + 1 < f.size(); ++k) v += dot(f[0], cross(f[k], f[k + 1])) / 6;
    }
    return v;
}

std::vector<Solid> furniture(const Scene& scene, double tolerance) {
    std::vector<Solid> out;
    for (const Surface& s : scene.surfaces) {
        if (const auto* box = std::get_if<BoxGeometry>(&s.geometry)) {
            // A box is its own bounds: no faces needed.
            if (!box->facing_in) out.push_back({{}, box->min, box->max});
            continue;
        }
        if (!std::holds_alternative<MeshGeometry>(s.geometry)) continue;
        const auto faces = faces_of(s);
        if (!outline(faces, tolerance).empty() || !(signed_volume(faces) > 0)) continue;
        Box box;
        for (const auto& f : faces) box.add(f);
        Solid solid{faces, box.lo, box.hi};
        out.push_back(std::move(solid));
    }
    return out;
}

bool inside_box(const Solid& s, const Vec3& x) {
    return x.x > s.lo.x && x.x < s.hi.x && x.y > s.lo.y && x.y < s.hi.y && x.z > s.lo.z &&
           x.z < s.hi.z;
}

struct Expansion {
    std::vector<Vec3> points;
    SensorGrid grid;
    std::string problem;  ///< empty when the grid is usable
};

Expansion expand(const Scene& scene, const Workplane& w, std::size_t max_points) {
    Expansion out;
    const double m = meters_per_unit(scene.units);
    const double height = w.height.value_or(kDefaultHeightM / m);
    const double border = w.border.value_or(kDefaultBorderM / m);
    std::vector<std::vector<Vec3>> floors;
    double extent = 0;
    for (const Surface& s : scene.surfaces) {
        if (std::find(w.surfaces.begin(), w.surfaces.end(), s.name) == w.surfaces.end()) continue;
        for (auto& f : faces_of(s)) {
            if (f.size() < 3 || polygon_normal(f).z < kUpwardCosine) continue;
            for (const Vec3& c : f) extent = std::max({extent, std::abs(c.x), std::abs(c.y)});
            floors.push_back(std::move(f));
        }
    }
    if (floors.empty()) {
        out.problem = "the named surfaces have no upward-facing horizontal face";
        return out;
    }
    const double tolerance = 1e-9 * std::max(1.0, extent);
    const std::vector<Edge> edges = outline(floors, tolerance);
    // The grid runs along the floor's longest outline edge, so a turned room gets a turned grid.
    Vec3 u_axis{1, 0, 0};
    double longest = 0;
    for (const Edge& e : edges) {
        const Vec3 d{e.b.x - e.a.x, e.b.y - e.a.y, 0};
        if (length(d) > longest) {
            longest = length(d);
            u_axis = normalized(d);
        }
    }
    const Vec3 v_axis = cross(Vec3{0, 0, 1}, u_axis);
    const auto flat = [&](const Vec3& x) { return Point2{dot(x, u_axis), dot(x, v_axis)}; };
    std::vector<FloorFace> faces;
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (const auto& f : floors) {
        FloorFace& face = faces.emplace_back();
        face.z = f[0].z;
        for (const Vec3& c : f) {
            const Point2 p = flat(c);
            face.corners.push_back(p);
            u0 = std::min(u0, p.u), u1 = std::max(u1, p.u);
            v0 = std::min(v0, p.v), v1 = std::max(v1, p.v);
        }
    }
    const double a = u1 - u0 - 2 * border, b = v1 - v0 - 2 * border;
    if (!(a > 0 && b > 0)) {
        out.problem = "the border leaves no area on the floor";
        return out;
    }
    // EN 12464-1: p = 0.2·5^log10(d), d the longer side of the area in metres.
    const double spacing =
        w.spacing.value_or(0.2 * std::pow(5.0, std::log10(std::max(a, b) * m)) / m);
    const double cells_u = std::ceil(a / spacing - 1e-9), cells_v = std::ceil(b / spacing - 1e-9);
    if (cells_u * cells_v > static_cast<double>(max_points)) {
        out.problem = "the grid has " + std::to_string(cells_u * cells_v) +
                      " cells, over the limit of " + std::to_string(max_points) + " points";
        return out;
    }
    const int nu = static_cast<int>(cells_u), nv = static_cast<int>(cells_v);
    const std::vector<Solid> solids = furniture(scene, tolerance);
    std::vector<std::pair<Point2, Point2>> outline2;
    for (const Edge& e : edges) outline2.emplace_back(flat(e.a), flat(e.b));
    for (int iv = 0; iv < nv; ++iv) {
        for (int iu = 0; iu < nu; ++iu) {
            const Point2 p{u0 + border + (iu + 0.5) * a / nu, v0 + border + (iv + 0.5) * b / nv};
            const auto face = std::find_if(faces.begin(), faces.end(), [&](const FloorFace& f) {
                return inside_polygon(f.corners, p);
            });
            if (face == faces.end()) continue;
            const bool near_edge =
                std::any_of(outline2.begin(), outline2.end(), [&](const auto& e) {
                    return distance_to_segment(p, e.first, e.second) < border - tolerance;
                });
            if (near_edge) continue;
            Vec3 x = u_axis * p.u + v_axis * p.v;
            x.z = face->z + height;
            const bool in_furniture = std::any_of(
                solids.begin(), solids.end(),
                [&](const Solid& s) { return s.faces.empty() ? inside_box(s, x) : s.contains(x); });
            if (in_furniture) continue;
            out.points.push_back(x);
            out.grid.cells.push_back({iu, iv});
        }
    }
    if (out.points.empty()) {
        out.problem = "no grid point lies on the floor outside furniture";
        return out;
    }
    out.grid.nu = nu;
    out.grid.nv = nv;
    out.grid.spacing = spacing;
    out.grid.origin = u_axis * (u0 + border) + v_axis * (v0 + border);
    out.grid.origin.z = faces.front().z + height;
    out.grid.u = u_axis * a;
    out.grid.v = v_axis * b;
    return out;
}

}  // namespace

std::vector<Problem> expand_workplanes(Scene& scene, const SceneLimits& limits) {
    std::vector<Problem> problems;
    std::size_t total = 0;
    for (const SensorSet& s : scene.sensors) total += s.workplane ? 0 : s.points.size();
    for (std::size_t i = 0; i < scene.sensors.size(); ++i) {
        SensorSet& s = scene.sensors[i];
        if (!s.workplane) continue;
        const std::size_t room =
            limits.max_sensor_points - std::min(total, limits.max_sensor_points);
        Expansion e = expand(scene, *s.workplane, room);
        if (!e.problem.empty()) {
            problems.push_back({"/sensors/" + std::to_string(i) + "/workplane", e.problem});
            continue;
        }
        total += e.points.size();
        e.grid.points = e.points;
        s.points = std::move(e.points);
        s.grid = std::move(e.grid);
    }
    return problems;
}

}  // namespace radiant
